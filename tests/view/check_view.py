#!/usr/bin/env python3
"""Checks a page of `tessera view` in headless Chromium (Debian's `chromium`, software WebGL).

check_view.py RESULT_DIR PAGE SCREENSHOT.png

Loads PAGE, reads the scene summary the page writes into <pre id="tessera-summary">, and checks:
no script error; the number of drawn elements of each layer equals the count read here from
RESULT_DIR's own files (doc/formats.md); moving the pointer over the canvas (its centre and points
around it) makes the hover line name a vertex and an element that exist in those files, as
window.tesseraPick does (when the files tell the counts); a screenshot shows the scene (not one flat
colour).
Prints one line per check; exit code 0 when all pass, 1 otherwise.
"""
import collections
import html
import json
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

CHROMIUM_FLAGS = ["--headless=new", "--no-sandbox", "--use-angle=swiftshader",
                  "--enable-unsafe-swiftshader", "--hide-scrollbars", "--window-size=1000,750",
                  "--virtual-time-budget=30000", "--no-first-run", "--disable-gpu-sandbox"]


def chromium(args, profile):
    exe = shutil.which("chromium") or shutil.which("chromium-browser")
    if not exe:
        sys.exit("check_view: chromium not found (scripts/install-deps.sh installs it)")
    return subprocess.run([exe, *CHROMIUM_FLAGS, "--user-data-dir=" + profile, *args],
                          capture_output=True, text=True, timeout=300)


def off_counts(path):
    """(vertices, faces, border edges) of an OFF file."""
    words = []
    with open(path) as f:
        for line in f:
            line = line.split("#")[0].split()
            words.extend(line)
    assert words[0].endswith("OFF"), path
    nv, nf = int(words[1]), int(words[2])
    at = 4 + 3 * nv
    edges = collections.Counter()
    for _ in range(nf):
        n = int(words[at])
        face = [int(w) for w in words[at + 1:at + 1 + n]]
        at += 1 + n
        for k in range(n):
            a, b = face[k], face[(k + 1) % n]
            edges[(min(a, b), max(a, b))] += 1
    return nv, nf, sum(1 for c in edges.values() if c == 1)


def ply_triangles(path):
    """Triangles of a PLY's faces fanned (sum of n - 2), ASCII or binary little-endian."""
    return ply_counts(path)[2]


def ply_counts(path):
    """(vertices, faces, triangles of the faces fanned) of a PLY, ASCII or binary little-endian."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    elements, current = [], None
    for line in header:
        w = line.split()
        if w[0] == "element":
            current = [w[1], int(w[2]), []]
            elements.append(current)
        elif w[0] == "property":
            current[2].append(w[1:])
    binary = "binary_little_endian" in header[1]
    sizes = {"char": "b", "uchar": "B", "int8": "b", "uint8": "B", "short": "h", "ushort": "H",
             "int": "i", "uint": "I", "int32": "i", "uint32": "I", "float": "f", "float32": "f",
             "double": "d"}
    body = data[end:] if binary else data[end:].decode().split()
    at, triangles = 0, 0
    for name, count, props in elements:
        for _ in range(count):
            for p in props:
                if p[0] == "list":
                    if binary:
                        fmt = "<" + sizes[p[1]]
                        n = struct.unpack_from(fmt, body, at)[0]
                        at += struct.calcsize(fmt) + n * struct.calcsize("<" + sizes[p[2]])
                    else:
                        n = int(body[at])
                        at += 1 + n
                    if name == "face":
                        triangles += n - 2
                else:
                    at += struct.calcsize("<" + sizes[p[0]]) if binary else 1
    count = {name: n for name, n, _ in elements}
    return count.get("vertex", 0), count.get("face", 0), triangles


def obj_counts(path):
    """(vertices, faces, triangles of the faces fanned) of an OBJ file."""
    vertices = faces = triangles = 0
    with open(path) as f:
        for line in f:
            words = line.split()
            if words and words[0] == "v":
                vertices += 1
            elif words and words[0] == "f":
                faces += 1
                triangles += len(words) - 3
    return vertices, faces, triangles


def mesh_counts(path):
    """(vertices, faces) of an OFF, PLY or OBJ file, or of a result directory's mesh.off; None for
    another format or a missing file."""
    if os.path.isdir(path):
        path = os.path.join(path, "mesh.off")
    if not os.path.exists(path):
        return None
    if path.lower().endswith(".obj"):
        return obj_counts(path)[:2]
    if path.lower().endswith(".off"):
        return off_counts(path)[:2]
    if path.lower().endswith(".ply"):
        return ply_counts(path)[:2]
    return None


def triangles(path):
    """Triangles of the faces fanned of an OFF, PLY or OBJ file, or of a result's mesh.off."""
    if os.path.isdir(path):
        path = os.path.join(path, "mesh.off")
    if path.lower().endswith(".obj"):
        return obj_counts(path)[2]
    if path.lower().endswith(".ply"):
        return ply_triangles(path)
    words = [w for line in open(path) for w in line.split("#")[0].split()]
    nv, nf, at, count = int(words[1]), int(words[2]), 4 + 3 * int(words[1]), 0
    for _ in range(nf):
        count += int(words[at]) - 2
        at += 1 + int(words[at])
    return count


def expected_layers(result):
    """{layer name: {count key: count}} from the result directory's files."""
    f = lambda name: os.path.join(result, name)
    if os.path.isfile(result):  # a report of tessera check
        report = json.load(open(result))
        problems = lambda key: sum(len(p["vertices"]) + len(p["faces"]) for p in report[key])
        layers = {"charts": {"triangles": triangles(report["input"])},
                  "problems": {"points": problems("problems")},
                  "notes": {"points": problems("notes")}}
        if "seam_edges" in report:
            layers["seams"] = {"segments": report["seam_edges"]}
        return layers
    if os.path.exists(f("opened.off")):
        _, faces, mesh_border = off_counts(f("mesh.off"))
        _, _, opened_border = off_counts(f("opened.off"))
        report = json.load(open(f("result.json")))
        quads = os.path.exists(f("quads.obj"))
        return {"quads" if quads else "surface": {"triangles": faces},
                "quad borders" if quads else "seams": {"segments": (opened_border - mesh_border) // 2},
                "corners": {"points": len(report["multipoints"])}}
    if os.path.exists(f("field.csv")):
        rows = sum(1 for _ in open(f("field.csv"))) - 1
        sing = json.load(open(f("singularities.json")))
        return {"field": {"segments": rows * sing["symmetry"]},
                "singularities": {"points": len(sing["singularities"])}}
    if os.path.exists(f("tiles.ply")):
        return {"tiles": {"triangles": ply_triangles(f("tiles.ply"))}}
    if os.path.exists(f("tiles.json")):  # a planar mosaic
        tiles = json.load(open(f("tiles.json")))["tiles"]
        report = json.load(open(f("report.json")))
        # A rectangle is two triangles, an ellipse a fan of 24 around its centre.
        per_tile = 24 if report["options"]["shape"] == "ellipse" else 2
        layers = {"tiles": {"elements": len(tiles), "triangles": per_tile * len(tiles),
                            "colours": "per triangle"}}
        image = report["image"]
        if os.path.exists(image["path"]):
            layers["image"] = {"triangles": 2, "texture": "%dx%d" % (image["width"], image["height"])}
        if os.path.exists(f("field.png")):
            width, height = png_size(f("field.png"))
            layers["field.png (field, edges red)"] = {"triangles": 2, "texture": "%dx%d" % (width, height)}
        return layers
    for name in ("resized.off", "deformed.off"):
        if os.path.exists(f(name)):
            layers = {"after": {"triangles": off_counts(f(name))[1]}}
            if name == "deformed.off" and mesh_counts(json.load(open(f("report.json"))).get("mesh", "")):
                layers["after"]["colours"] = "per vertex"  # stretch, from the input mesh
                # The legend's top is the largest local stretch ratio, as the report gives it.
                top = json.load(open(f("report.json")))["stretch_ratio"]["max"]
                layers["after"]["name"] = "after (stretch σ1/σ2: white 1 to red %.6g)" % top
            for before in ("vulnerability.ply", "regions.ply"):
                if os.path.exists(f(before)):
                    layers["before (%s)" % before] = {"triangles": ply_triangles(f(before))}
            return layers
    sys.exit("check_view: no result of a known kind in " + result)


def png_size(path):
    """(width, height) of a PNG file."""
    with open(path, "rb") as f:
        return struct.unpack(">II", f.read(24)[16:24])


def planar_tile_figures(tile):
    """The start of a planar mosaic tile's hover figures, from its line of tiles.json."""
    return "colour %d, %d, %d, size %g x %g px, angle %g°, centre (%g, %g) px" % (
        *tile["color"], tile["width"], tile["height"], tile["angle"] * 180 / math.pi, *tile["center"])


def layer_name(name):
    """A page's layer name without its colour legend (" (stretch ...)")."""
    return re.sub(r" \(stretch.*\)$", "", name)


def drawn_layer(summary, name):
    """The summary of layer `name` (the name with or without a legend)."""
    for layer in summary["layers"]:
        if layer_name(layer["name"]) == name:
            return layer
    return {}


def hover_layers(result):
    """{layer name: (vertices, elements[, figures])} that hover may name, from the result's own
    files; figures(element id) is text its hover figures must begin with; vertices None: hover
    names no vertex there."""
    f = lambda name: os.path.join(result, name)
    layers = {}
    if os.path.isfile(result):  # a report of tessera check
        report = json.load(open(result))
        charts = len(report.get("charts", []))
        if not charts:
            return {}
        return {"charts": (mesh_counts(report["input"])[0], charts,
                           lambda i: "chart %d of %d," % (i, charts))}
    report = json.load(open(f("report.json"))) if os.path.exists(f("report.json")) else {}
    if isinstance(report.get("mesh"), str) and mesh_counts(report["mesh"]):
        layers["surface"] = layers["before"] = mesh_counts(report["mesh"])
    if os.path.exists(f("opened.off")):
        nv, nf = off_counts(f("mesh.off"))[:2]
        if os.path.exists(f("quads.obj")):
            quads = json.load(open(f("result.json")))["quad_tiles"]
            return {"quads": (nv, len(quads))}
        return {"surface": (nv, nf)}
    if os.path.exists(f("tiles.ply")):
        tiles = json.load(open(f("tiles.json")))["tiles"]
        layers["tiles"] = ply_counts(f("tiles.ply"))[:2] + (lambda i: "face %d," % tiles[i]["face"],)
    elif os.path.exists(f("tiles.json")):  # a planar mosaic: hover names tiles, no vertices
        tiles = json.load(open(f("tiles.json")))["tiles"]
        layers["tiles"] = (None, len(tiles), lambda i: planar_tile_figures(tiles[i]))
    for name in ("resized.off", "deformed.off"):
        if os.path.exists(f(name)):
            layers["after"] = off_counts(f(name))[:2]
            if name == "deformed.off" and "before" in layers:
                layers["after"] += (lambda i: "stretch σ1/σ2 at its corners ",)
    for before in ("vulnerability.ply", "regions.ply"):
        if os.path.exists(f(before)):
            layers["before (%s)" % before] = ply_counts(f(before))[:2]
    return layers


# Run after the page's script: moves the pointer over the canvas (at the centre first, then around
# it) as a user would, and records what the hover line shows and what window.tesseraPick returns.
HOVER_PROBE = """<script type="module">
const canvas = document.querySelector('canvas');
const hover = document.getElementById('hover');
const pause = () => new Promise((done) => setTimeout(done, 100));
const probes = [];
for (const [fx, fy] of [[0.5, 0.5], [0.45, 0.5], [0.55, 0.5], [0.5, 0.42], [0.5, 0.58],
                        [0.4, 0.4], [0.6, 0.6], [0.4, 0.6], [0.6, 0.4], [0.3, 0.5], [0.7, 0.5]]) {
  const x = Math.round(fx * window.innerWidth), y = Math.round(fy * window.innerHeight);
  hover.textContent = '';
  canvas.dispatchEvent(new PointerEvent('pointermove', { clientX: x, clientY: y, bubbles: true }));
  await pause();
  const picked = window.tesseraPick ? window.tesseraPick(x, y) : null;
  probes.push({ x, y, shown: hover.textContent, picked: picked && picked.text });
}
const out = document.createElement('pre');
out.id = 'tessera-hover';
out.textContent = JSON.stringify(probes);
document.body.append(out);
</script>
"""


def check_hover(dom, layers):
    """Failures of the hover probes: the hover line must name a layer of `layers` with a vertex and
    an element id below that layer's counts, the same as window.tesseraPick, at least once."""
    match = re.search(r'<pre id="tessera-hover">(.*?)</pre>', dom, re.S)
    if not match:
        return ["the hover probe did not finish"]
    failures, named = [], 0
    for probe in json.loads(html.unescape(match.group(1))):
        shown = probe["shown"]
        if not shown:
            continue
        where = "hover at (%d, %d) shows %r" % (probe["x"], probe["y"], shown)
        ids = re.match(r"(.+): (?:vertex (\d+), )?(\w+) (\d+)", shown)
        if shown != probe["picked"]:
            failures.append(where + " but tesseraPick gives %r" % probe["picked"])
        elif not ids or layer_name(ids.group(1)) not in layers:
            failures.append(where + ": not a layer of " + ", ".join(sorted(layers)))
        else:
            nv, ne = layers[layer_name(ids.group(1))][:2]
            figures = layers[layer_name(ids.group(1))][2:]
            if (nv is None) != (ids.group(2) is None):
                failures.append(where + (": names a vertex" if nv is None else ": names no vertex"))
            elif (nv is not None and int(ids.group(2)) >= nv) or int(ids.group(4)) >= ne:
                failures.append(where + ": the files have %s vertices and %d %ss" % (nv, ne, ids.group(3)))
            elif figures and not shown.startswith("%s (%s" % (ids.group(0), figures[0](int(ids.group(4))))):
                failures.append(where + ": the files give %s (%s...)" % (ids.group(0), figures[0](int(ids.group(4)))))
            else:
                print("ok: %s (%s vertices, %d %ss)" % (where, nv, ne, ids.group(3)))
                named += 1
    if not named:
        failures.append("hover named no element at any of the probed points")
    return failures


def png_pixels(path):
    """(width, height, rows of bytes, bytes per pixel) of an 8-bit RGB or RGBA PNG."""
    with open(path, "rb") as f:
        data = f.read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    at, idat = 8, b""
    while at < len(data):
        n, kind = struct.unpack(">I4s", data[at:at + 8])
        chunk = data[at + 8:at + 8 + n]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", chunk[:10])
            assert depth == 8 and colour in (2, 6), "not an 8-bit RGB(A) PNG"
        elif kind == b"IDAT":
            idat += chunk
        at += 12 + n
    bpp = 3 if colour == 2 else 4
    raw, stride, rows, prev = zlib.decompress(idat), width * bpp, [], bytearray(width * bpp)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return width, height, rows, bpp


def main():
    result, page, shot = sys.argv[1:4]
    failures = []
    hover = hover_layers(result)
    with tempfile.TemporaryDirectory() as profile:
        probed = page
        if hover:
            probed = os.path.join(profile, "probed.html")
            with open(page, encoding="utf-8") as original, open(probed, "w", encoding="utf-8") as out:
                out.write(original.read().replace("</body>", HOVER_PROBE + "</body>"))
        dom = chromium(["--dump-dom", "file://" + os.path.abspath(probed)], profile).stdout
        match = re.search(r'<pre id="tessera-summary">(.*?)</pre>', dom, re.S)
        if not match or not match.group(1).strip():
            print("FAIL: the page wrote no scene summary (the script did not finish)")
            return 1
        summary = json.loads(html.unescape(match.group(1)))
        if os.path.exists(shot):
            os.remove(shot)
        chromium(["--screenshot=" + os.path.abspath(shot), "file://" + os.path.abspath(page)], profile)
    print("summary:", json.dumps(summary))
    if summary["errors"]:
        failures.append("script errors: %s" % summary["errors"])
    for name, key, count in [(n, k, c) for n, counts in expected_layers(result).items()
                             for k, c in counts.items()]:
        got = drawn_layer(summary, name).get(key)
        line = "layer %s: %s %s drawn, %s in the files" % (name, got, key, count)
        print(("ok: " if got == count else "FAIL: ") + line)
        if got != count:
            failures.append(line)
    for line in check_hover(dom, hover) if hover else []:
        print("FAIL: " + line)
        failures.append(line)
    if not os.path.exists(shot):
        failures.append("no screenshot")
    else:
        width, height, rows, bpp = png_pixels(shot)
        colours = collections.Counter(row[i:i + 3] for row in rows[::4] for i in range(0, len(row), 4 * bpp))
        background, most = colours.most_common(1)[0]
        drawn_fraction = 1 - most / sum(colours.values())
        line = "screenshot %dx%d: %d colours, %.1f%% not background" % (
            width, height, len(colours), 100 * drawn_fraction)
        ok = len(colours) > 20 and drawn_fraction > 0.03
        print(("ok: " if ok else "FAIL: ") + line)
        if not ok:
            failures.append(line)
    for f in failures:
        print("check_view: FAIL:", f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
