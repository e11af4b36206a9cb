#!/usr/bin/env bash
# Installs the dependencies, builds, and renders the bundled examples into out/:
#   out/curves.png          every curve kind, adaptive (blue) vs uniform (orange)
#   out/curves.txt          their segment counts and measured errors
#   out/flatten-*.json      `casteljau flatten --json` on the example paths
#   out/svg/*.png           the example SVG files rendered by `casteljau render`
#   out/svg/stats.json      their render statistics (one JSON object per file)
#   out/compare/            `casteljau compare` on the curves example: images, heat map, report.md
#   out/patch/              `casteljau patch` on the patch examples: shaded, wireframe, OBJ meshes, stats.json
#   out/app.png             examples/app: the library used as a drawing application would
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCASTELJAU_BUILD_BENCH=ON
cmake --build build -j "$(nproc)"

mkdir -p out
rm -f out/patch/stats.json
build/examples/curves_image out/curves.png 0.25 | tee out/curves.txt
build/examples/app/casteljau_app out/app.png
while read -r name data; do
  for method in adaptive uniform; do
    build/cli/casteljau flatten --path "$data" --flatten "$method" --json > "out/flatten-$name-$method.json"
    printf '%-14s %-9s %s\n' "$name" "$method" "$(cut -c1-60 "out/flatten-$name-$method.json")"
  done
done < examples/paths.txt
build/cli/casteljau render examples/svg/*.svg -o out/svg/ --scale 2 --stats out/svg/stats.json
echo "rendered $(ls out/svg/*.png | wc -l) SVG examples into out/svg/"
build/cli/casteljau compare examples/svg/curves.svg -o out/compare --segments 8 > /dev/null
echo "adaptive vs uniform report: out/compare/report.md"
mkdir -p out/patch
for f in examples/patch/*.map examples/patch/*.bpt examples/patch/*.json; do
  name=$(basename "${f%.*}")
  build/cli/casteljau patch "$f" -o "out/patch/$name.png" --stats - >> out/patch/stats.json
  build/cli/casteljau patch "$f" -o "out/patch/$name-wire.png" --wireframe --texture none \
    --mesh "out/patch/$name.obj"
done
echo "rendered $(ls out/patch/*.png | wc -l) patch images and meshes into out/patch/"
echo "examples written to $(pwd)/out"
