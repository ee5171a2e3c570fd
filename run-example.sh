#!/usr/bin/env bash
# Sets up, builds and runs consistent-remesh on the landmarked four-legged
# animals of SHREC'07 and Spot (../shared/data), with the base domain built
# from model 381. Results go to ./results (or the folder given as $1).
set -euo pipefail
cd "$(dirname "$0")"
./setup.sh

data="${CMP_SHARED_DATA_DIR:-../shared/data}"
if [ ! -d "$data/shrec07-fourleg" ]; then
  echo "run-example: no sample data in '$data' (set CMP_SHARED_DATA_DIR)" >&2
  exit 2
fi
output="${1:-results}"
args=()
for landmarks in "$data"/shrec07-fourleg/*.vts; do
  args+=(--mesh "${landmarks%.vts}.off" --landmarks "$landmarks")
done
args+=(--mesh "$data/spot/spot.obj" --landmarks "$data/spot/spot_shrec07.pinned")
build/bin/consistent-remesh "${args[@]}" --base-domain-from 0 --output "$output"
echo "run-example: wrote $output/report.json and $output/base_domain.vtp"
