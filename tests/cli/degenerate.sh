#!/usr/bin/env bash
# degenerate.sh CLI SOURCE.off DIR: every command on degenerate geometry gives a result or one clear
# error, never a crash, a hang or a NaN (issue 17, item 3). From SOURCE (a closed mesh) it writes
# into DIR: a single triangle; SOURCE scaled by 1e300 and by 1e-300; SOURCE with a collinear
# (zero-area) face and two vertices at one point; a strip of slivers 1e-12 high; a closed surface
# whose vertices all lie on one line. Each command must exit with the code given below (a signal,
# a timeout or another code fails), an error must name the cause, and no text output of a run
# that succeeded may hold a NaN or an infinity.
set -u
cli=$1; source=$2; dir=$3
rm -rf "$dir"; mkdir -p "$dir"
python3 - "$source" "$dir" <<'PY'
import sys
src, out = sys.argv[1], sys.argv[2]
rows = [l.split('#')[0].split() for l in open(src)]
rows = [r for r in rows if r]
nv, nf = int(rows[1][0]), int(rows[1][1])
V = [[float(x) for x in rows[2 + i][:3]] for i in range(nv)]
F = [[int(x) for x in rows[2 + nv + i][1:]] for i in range(nf)]
def write(name, V, F):
    with open(out + '/' + name, 'w') as f:
        f.write('OFF\n%d %d 0\n' % (len(V), len(F)))
        f.writelines('%.17g %.17g %.17g\n' % tuple(v) for v in V)
        f.writelines('%d %s\n' % (len(p), ' '.join(map(str, p))) for p in F)
write('single-triangle.off', [[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
write('huge.off', [[c * 1e300 for c in v] for v in V], F)
write('tiny.off', [[c * 1e-300 for c in v] for v in V], F)
W = [list(v) for v in V]
a, b, c = F[0]
W[c] = [(W[a][k] + W[b][k]) / 2 for k in range(3)]   # a collinear face
a, b, c = F[len(F) // 2]
W[b] = list(W[a])                                     # two vertices at one point
write('degenerate-faces.off', W, F)
n = 200
S = [[float(i), 0.0, 0.0] for i in range(n)] + [[i + 0.5, 1e-12, 0.0] for i in range(n)]
write('slivers.off', S, [t for i in range(n - 1) for t in ([i, i + 1, n + i], [i + 1, n + i + 1, n + i])])
write('on-a-line.off', [[float(i), 0, 0] for i in range(4)], [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]])
PY
[ -s "$dir/huge.off" ] || { echo "degenerate.sh: could not write the inputs" >&2; exit 1; }

failures=0
run() { # run CODE PATTERN INPUT COMMAND [ARGS...]
  local code=$1 pattern=$2 input=$3 command=$4; shift 4
  local out rc outdir=$dir/out-${input%.off}-$command
  local args=("$command" "$dir/$input" "$@")
  case $command in
    info) ;;
    render) args+=(--out "$outdir.png") ;;
    *) args+=(--out "$outdir" --force) ;;
  esac
  out=$(timeout 120 "$cli" "${args[@]}" 2>&1); rc=$?
  if [ "$rc" -ne "$code" ] || ! printf '%s' "$out" | grep -qF -- "$pattern"; then
    printf '%s\n' "$out" | tail -5
    echo "degenerate.sh: $command $input: exit code $rc (expected $code), output lacks '$pattern'?" >&2
    failures=$((failures + 1)); return
  fi
  if [ "$rc" -eq 0 ] && [ -d "$outdir" ] &&
     grep -rIilwE -- 'nan|inf|infinity' "$outdir" >/dev/null 2>&1; then
    echo "degenerate.sh: $command $input: a NaN or infinity in $(grep -rIilwE -- 'nan|inf|infinity' "$outdir" | head -1)" >&2
    failures=$((failures + 1)); return
  fi
  echo "ok: $command $input -> $rc"
}

commands=(info cut quadrangulate field mosaic resize render)
extra() { case $1 in mosaic) echo --tiles 100 ;; resize) echo --scale 2,1,1 ;; esac; }
for c in "${commands[@]}"; do
  run 0 "" single-triangle.off "$c" $(extra "$c")
  run 0 "" degenerate-faces.off "$c" $(extra "$c")
  run 0 "" slivers.off "$c" $(extra "$c")
  run 1 "beyond 1e150" huge.off "$c" $(extra "$c")
  run 1 "below 1e-150" tiny.off "$c" $(extra "$c")
  run 1 "every face has zero area" on-a-line.off "$c" $(extra "$c")
done
[ "$failures" -eq 0 ] || { echo "degenerate.sh: $failures failures" >&2; exit 1; }
echo "degenerate.sh: every command gave a result or a clear error on every degenerate input"
