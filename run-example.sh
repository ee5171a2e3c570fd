#!/usr/bin/env bash
# Sets up, builds and runs consistent-remesh. With the shared sample data
# beside the project (../shared/data, or $CMP_SHARED_DATA_DIR) it processes
# the landmarked SHREC'07 four-legged animals and Spot, with the base domain
# built from model 381; otherwise it runs on the example collection shipped
# in Data/examples. Results go to ./results (or the folder given as $1).
set -euo pipefail
cd "$(dirname "$0")"
./setup.sh

output="${1:-results}"
data="${CMP_SHARED_DATA_DIR:-../shared/data}"
args=()
if [ -d "$data/shrec07-fourleg" ] && [ -d "$data/spot" ]; then
  echo "run-example: the four-legged collection in $data"
  for landmarks in "$data"/shrec07-fourleg/*.vts; do
    args+=(--mesh "${landmarks%.vts}.off" --landmarks "$landmarks")
  done
  args+=(--mesh "$data/spot/spot.obj" --landmarks "$data/spot/spot_shrec07.pinned")
else
  echo "run-example: the example collection shipped in Data/examples"
  args=(--mesh Data/examples/blob.off --landmarks Data/examples/blob.vts
        --mesh Data/examples/capsule.obj --landmarks Data/examples/capsule.pinned
        --mesh Data/examples/peanut.off --landmarks Data/examples/peanut.csv)
fi
build/bin/consistent-remesh "${args[@]}" --base-domain-from 0 --output "$output"
echo "run-example: wrote $output/report.json, base_domain.vtp, the NAME.remesh.vtp remeshes and collection.vtm"
