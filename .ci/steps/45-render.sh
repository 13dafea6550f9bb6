#!/usr/bin/env bash
# End-to-end check of `dissect render`, `rasterize`, `voxelize` and
# `solve --render`: solve the built-in example, check it with
# the independent checkers (.ci/lib/check.sh), write every output format, check the STL files
# with an independent Python reader (closed, manifold, volume), and turn
# pictures and meshes back into figures with exact cell counts. Seconds.
set -euo pipefail
cd "$(dirname "$0")/../.."
. .ci/lib/check.sh
root=$PWD
target=${CARGO_TARGET_DIR:-$root/target}
cargo build --release -p dissect-cli --quiet
bin=$target/release/dissect
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

a=examples/squares-3-4.txt
b=examples/square-5.txt
"$bin" solve "$a" "$b" --threads 2 --quiet -o "$out/sq.json" --render "$out/views"
check_solution square "$out/sq.json" "$a" "$b" | tee "$out/v.txt"
grep -q '^valid: ' "$out/v.txt"
test -s "$out/views/dissection.svg" && test -s "$out/views/cut-sheet.svg"

"$bin" render "$out/sq.json" --figures "$a" "$b" --format svg -o "$out/sq.svg"
"$bin" render "$out/sq.json" --figures "$a" "$b" --format png -o "$out/sq.png" --cut-sheet
"$bin" render "$out/sq.json" --figures "$a" "$b" --format stl -o "$out/stl" --thickness 3 --clearance 0
"$bin" render "$out/sq.json" --figures "$a" "$b" --format ldraw -o "$out/ldr"
grep -q '<path' "$out/sq.svg"
head -c 8 "$out/sq.png" | od -An -tx1 | grep -q '89 50 4e 47'
test -s "$out/cut-sheet.svg"
ls "$out/ldr"/*.ldr >/dev/null

# Every STL: closed, every edge used once in each direction, volume = cells x
# cell area (mm^2, default 10 x 10) x 3.
cat > "$out/stl_check.py" <<'PY'
import json, struct, sys, glob, os
sol = json.load(open(sys.argv[1]))
cell_area = float(sys.argv[3]) if len(sys.argv) > 3 else 100.0
areas = [len(p) for p in sol["figures"][0]["pieces"]]
files = sorted(glob.glob(os.path.join(sys.argv[2], "piece-*.stl")))
assert len(files) == len(areas), (files, areas)
for f, area in zip(files, areas):
    data = open(f, "rb").read()
    n = struct.unpack_from("<I", data, 80)[0]
    assert len(data) == 84 + 50 * n, f
    edges, vol = {}, 0.0
    for k in range(n):
        v = struct.unpack_from("<9f", data, 84 + 50 * k + 12)
        t = [v[0:3], v[3:6], v[6:9]]
        for i in range(3):
            e = (t[i], t[(i + 1) % 3])
            edges[e] = edges.get(e, 0) + 1
        a, b, c = t
        vol += (a[0]*(b[1]*c[2]-b[2]*c[1]) - a[1]*(b[0]*c[2]-b[2]*c[0]) + a[2]*(b[0]*c[1]-b[1]*c[0])) / 6
    bad = [e for e, m in edges.items() if m != 1 or edges.get((e[1], e[0])) != 1]
    assert not bad, f"{f}: {len(bad)} edges not shared by exactly two triangles"
    want = area * cell_area * 3.0
    assert abs(vol - want) < 1e-3 * want, (f, vol, area, want)
    print(f"{os.path.basename(f)}: {n} triangles, closed, volume {vol:.1f} mm^3")
PY
python3 "$out/stl_check.py" "$out/sq.json" "$out/stl"

# tri3 and hex: solve, verify, every picture, the page and the step sheets,
# and STL volumes of true triangles (sqrt(3)/4 x 10^2) and hexagons
# (sqrt(3)/2 x 10^2, 10 mm between centres).
printf '###\n###\n' > "$out/t-hexagon.txt"
printf '######\n' > "$out/t-bar.txt"
printf '.##\n###\n.##\n' > "$out/h-hexagon.txt"
printf '####\n###\n' > "$out/h-trapezoid.txt"
for l in tri3 hex; do
  case $l in tri3) a2=$out/t-hexagon.txt b2=$out/t-bar.txt cell=43.30127018922193 ;;
             hex) a2=$out/h-hexagon.txt b2=$out/h-trapezoid.txt cell=86.60254037844386 ;; esac
  "$bin" solve --lattice $l "$a2" "$b2" --threads 2 --quiet --time-limit 10 -o "$out/$l.json"
  check_solution $l "$out/$l.json" "$a2" "$b2" | grep -q '^valid: '
  "$bin" render "$out/$l.json" --figures "$a2" "$b2" --format png -o "$out/$l.png"
  head -c 8 "$out/$l.png" | od -An -tx1 | grep -q '89 50 4e 47'
  "$bin" render "$out/$l.json" --figures "$a2" "$b2" --format html -o "$out/$l.html"
  grep -q "\"lattice\":\"$l\"" "$out/$l.html"
  if grep -Eq '(src|href)="(https?:|/)' "$out/$l.html"; then echo "$l.html fetches something" >&2; exit 1; fi
  "$bin" render "$out/$l.json" --figures "$a2" "$b2" --format steps -o "$out/$l-steps"
  test "$(ls "$out/$l-steps"/steps-*.svg | wc -l)" = 2
  "$bin" render "$out/$l.json" --figures "$a2" "$b2" --format stl -o "$out/$l-stl" --thickness 3 --clearance 0
  python3 "$out/stl_check.py" "$out/$l.json" "$out/$l-stl" "$cell"
  if "$bin" render "$out/$l.json" --figures "$a2" "$b2" --format ldraw -o "$out/$l-ldr" 2>"$out/err"; then
    echo "LDraw must be refused on $l" >&2; exit 1
  fi
  grep -q 'LDraw' "$out/err"
done

# Pictures to figures with exact cell counts.
cat > "$out/disc.svg" <<'SVG'
<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200"><circle cx="100" cy="100" r="80" fill="black"/></svg>
SVG
cat > "$out/small.svg" <<'SVG'
<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200"><circle cx="100" cy="100" r="60" fill="black"/></svg>
SVG
"$bin" rasterize "$out/disc.svg" --lattice square --cells 144 -o "$out/d1.txt"
"$bin" info --lattice square "$out/d1.txt" | grep -q ': 144 cells'
"$bin" rasterize "$out/disc.svg" --lattice tri4 --cells 128 -o "$out/d2.txt"
"$bin" info --lattice tri4 "$out/d2.txt" | grep -q ': 128 cells'
"$bin" rasterize "$out/disc.svg" "$out/disc.svg" "$out/small.svg" --lattice cubic --cells 56 -o "$out/d3.txt"
"$bin" info --lattice cubic "$out/d3.txt" | grep -q ': 56 cells'
"$bin" rasterize "$out/sq.png" --lattice square --cells 100 -o "$out/d4.txt"
"$bin" info --lattice square "$out/d4.txt" | grep -q ': 100 cells'

# A cubic dissection to STL and back.
printf '##\n##\n\n##\n##\n' > "$out/cube.txt"
printf '####\n####\n' > "$out/slab.txt"
cat > "$out/cubic.json" <<'JSON'
{"format":"dissection-solution/1","lattice":"cubic","mirror":false,"figures":[
 {"name":"cube.txt","pieces":[[[0,0,0],[1,0,0],[0,1,0],[1,1,0]],[[0,0,1],[1,0,1],[0,1,1],[1,1,1]]]},
 {"name":"slab.txt","pieces":[[[0,0,0],[1,0,0],[0,1,0],[1,1,0]],[[2,0,0],[3,0,0],[2,1,0],[3,1,0]]]}]}
JSON
check_solution cubic "$out/cubic.json" "$out/cube.txt" "$out/slab.txt" | grep -q '^valid: '
"$bin" render "$out/cubic.json" --figures "$out/cube.txt" "$out/slab.txt" --format stl -o "$out/cstl" --clearance 0
"$bin" voxelize "$out/cstl/piece-01-A.stl" --cells 4 -o "$out/v.txt"
diff <(printf '##\n##\n') "$out/v.txt"
"$bin" render "$out/cubic.json" --figures "$out/cube.txt" "$out/slab.txt" --format png -o "$out/cubic.png"

# Bad input: exit code 2 and the file named.
if "$bin" rasterize "$a" --cells 10 2>"$out/err.txt"; then echo "a text file was taken for a picture"; exit 1; fi
grep -q "squares-3-4.txt: not a picture" "$out/err.txt"
echo "render e2e: ok"
