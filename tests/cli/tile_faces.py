#!/usr/bin/env python3
"""Checks that tiles.json of `tessera mosaic` names faces of the input mesh (face ids below the
input's triangle count) when the mosaic ran on a mesh remeshed for its field (report.json's
field.refined_mesh), and prints "input faces: ok" then; exits 1 with the reason otherwise."""
import json
import sys

report, tiles, input_faces = sys.argv[1], sys.argv[2], int(sys.argv[3])
refined = json.load(open(report))["field"].get("refined_mesh")
if not refined or refined["vertices_added"] <= 0:
    sys.exit("the mesh was not remeshed")
largest = max(t["face"] for t in json.load(open(tiles))["tiles"])
if largest >= input_faces:
    sys.exit(f"tiles.json names face {largest}, the input has {input_faces}")
print("input faces: ok")
