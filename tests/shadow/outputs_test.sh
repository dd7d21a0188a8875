#!/usr/bin/env bash
# The SVG, DXF and CSV outputs of `penumbra shadows`, read by real tools: the SVG by
# xmllint (libxml2), the DXF by ezdxf (its auditor must find no error, and every
# polyline's world coordinates must be the JSON's), the CSV by Python's csv module
# (areas add up per face). Usage: outputs_test.sh PENUMBRA SOURCE_DIR
set -euo pipefail
penumbra=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python=/usr/bin/python3

# (the last three with exact joint umbrae: curved rings, arcs of ellipses drawn as SVG arcs,
# a mesh face with a hole)
for entry in every-kind shadow-cube-point shadow-shared-face linear-fig5 \
  "linear-joint-umbra --joint-umbrae" "linear-joint-ellipse --joint-umbrae" \
  "linear-joint-mesh --joint-umbrae"; do
  read -r scene flags <<<"$entry"
  file="$source_dir/fixtures/scenes/$scene.json"
  for view in top faces camera; do
    if [ "$view" = camera ] && ! grep -q '"camera"' "$file"; then continue; fi
    # shellcheck disable=SC2086 # flags: zero or more words
    "$penumbra" shadows "$file" $flags -o "$work/$scene.json" --svg "$work/$scene-$view.svg" \
      --view "$view" --dxf "$work/$scene.dxf" --report "$work/$scene.csv" --loops
    xmllint --noout "$work/$scene-$view.svg"
    grep -q '<path' "$work/$scene-$view.svg"
    if [ "$scene" = linear-joint-ellipse ]; then  # its umbra and penumbra meet along an ellipse
      grep -Eq ' A[0-9.e+-]+ [0-9.e+-]+ [0-9.e+-]+ [01] [01] ' "$work/$scene-$view.svg"
    fi
  done
  "$python" - "$work/$scene.json" "$work/$scene.dxf" "$work/$scene.csv" <<'PY'
import csv, json, sys
import ezdxf
from ezdxf import recover

loops = json.load(open(sys.argv[1]))
doc, auditor = recover.readfile(sys.argv[2])
assert not auditor.has_errors, [str(e) for e in auditor.errors]
doc = ezdxf.readfile(sys.argv[2])

# Expected rings per layer from the JSON, in world coordinates.
expected = {}
def add(layer, ring):
    expected.setdefault(layer, []).append(ring)
for face in loops["faces"]:
    boundary = face["boundary"]  # a ring, or {"outer", "holes"} for a face with holes
    for ring in ([boundary["outer"]] + boundary["holes"] if isinstance(boundary, dict)
                 else [boundary]):
        add("faces", ring)
    for light in face["lights"]:
        if light.get("beyond_range"):
            continue
        for kind in ("shadow", "umbra", "penumbra", "lit"):
            for polygon in light[kind]["polygons"]:
                add(f'{light["light"]}-{kind}', polygon["outer"])
                for hole in polygon["holes"]:
                    add(f'{light["light"]}-{kind}', hole)

found = {}
for entity in doc.modelspace():
    assert entity.dxftype() == "LWPOLYLINE", entity.dxftype()
    assert entity.closed
    found.setdefault(entity.dxf.layer, []).append([list(v) for v in entity.vertices_in_wcs()])
assert sorted(found) == sorted(expected), (sorted(found), sorted(expected))
for layer, rings in expected.items():
    got = found[layer]
    assert len(got) == len(rings), layer
    for ring, back in zip(rings, got):
        assert len(ring) == len(back)
        for p, q in zip(ring, back):
            assert all(abs(a - b) <= 1e-9 * max(1.0, abs(a)) for a, b in zip(p, q)), (layer, p, q)
    assert doc.layers.has_entry(layer), layer

rows = list(csv.DictReader(open(sys.argv[3])))
assert rows and set(rows[0]) >= {"object", "face", "light", "face_area", "shadow_area", "lit_area",
                                 "shadow_percent", "faces_away"}
for row in rows:
    if row["beyond_range"] == "true":
        continue
    face, shadow, lit = float(row["face_area"]), float(row["shadow_area"]), float(row["lit_area"])
    assert abs(face - shadow - lit) <= 1e-9 * max(1.0, face), row
    assert abs(float(row["shadow_percent"]) - 100 * shadow / face) <= 1e-9, row
    umbra, penumbra = float(row["umbra_area"]), float(row["penumbra_area"])
    assert abs(umbra + penumbra - shadow) <= 1e-9 * max(1.0, face), row
    # the JSON's areas (curved ones with --joint-umbrae)
    light = next(l for f in loops["faces"] if f["object"] == row["object"]
                 and str(f["face"]) == row["face"] for l in f["lights"] if l["light"] == row["light"])
    if light["umbra"]["polygons"] or light["penumbra"]["polygons"]:
        assert abs(umbra - light["umbra"]["area"]) <= 1e-9 * max(1.0, face), (row, light["umbra"]["area"])
        assert abs(penumbra - light["penumbra"]["area"]) <= 1e-9 * max(1.0, face), row
    if row["faces_away"] == "true":
        assert lit == 0, row
print(f"{sys.argv[1]}: DXF and CSV read back: {sum(len(r) for r in found.values())} polylines, {len(rows)} rows")
PY
done
echo "outputs: SVG, DXF and CSV read by xmllint, ezdxf and csv"

# Exact joint umbrae in the JSON (--joint-umbrae): rings with "arcs" whose conics (six
# rationals in the face's frame) vanish at the ring points they span, to the densification.
"$penumbra" shadows "$source_dir/fixtures/scenes/linear-joint-umbra.json" --joint-umbrae \
  -o "$work/joint.json"
"$python" - "$work/joint.json" <<'PY'
import json, sys
from fractions import Fraction

document = json.load(open(sys.argv[1]))
joint_arcs = 0
for face in document["faces"]:
    for light in face["lights"]:
        if not light["joint_occlusion"]:
            continue
        for region in ("umbra", "penumbra"):
            axes = light[region]["axes"]
            origin = [float(Fraction(k)) for k in axes["origin"]]
            u = [float(Fraction(k)) for k in axes["u"]]
            v = [float(Fraction(k)) for k in axes["v"]]
            uu, vv = sum(k * k for k in u), sum(k * k for k in v)
            for polygon in light[region]["polygons"]:
                rings = [(polygon["outer"], polygon["arcs"])] + list(
                    zip(polygon["holes"], polygon["hole_arcs"]))
                for ring, arcs in rings:
                    for arc in arcs:
                        # last == len(ring): the arc ends at the ring's first point
                        assert 0 <= arc["first"] < arc["last"] <= len(ring), arc
                        a, b, c, d, e, f = (float(Fraction(k)) for k in arc["conic"])
                        joint_arcs += arc["joint"]
                        # frame coordinates of a world point (the axes are orthogonal)
                        for point in (ring + ring[:1])[arc["first"]:arc["last"] + 1]:
                            w = [point[k] - origin[k] for k in range(3)]
                            s = sum(w[k] * u[k] for k in range(3)) / uu
                            t = sum(w[k] * v[k] for k in range(3)) / vv
                            value = a * s * s + b * s * t + c * t * t + d * s + e * t + f
                            scale = abs(d) + abs(e) + abs(f) + abs(a) + abs(b) + abs(c)
                            assert abs(value) <= 1e-6 * scale, (arc, point, value)
assert joint_arcs > 0, "no joint arc"
PY
