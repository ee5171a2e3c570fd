#!/usr/bin/env bash
# Installs the Debian packages this project needs (once; later runs only
# check), then configures and builds it in ./build.
# Usage: ./setup.sh            (set CMP_BUILD_DIR to build elsewhere)
set -euo pipefail
cd "$(dirname "$0")"

# ParaView 5.11 (with its own VTK 9.2) and what find_package(ParaView) needs;
# clang and its sanitizer runtimes for the readers' libFuzzer targets.
# Never add libvtk9-dev: it conflicts with python3-paraview.
packages=(
  cmake g++ ninja-build pkg-config
  paraview-dev python3-paraview python3-mpi4py python3-numpy
  libeigen3-dev libgtest-dev xvfb
  libcgal-demo
  clang libclang-rt-14-dev
  qtbase5-dev qttools5-dev libqt5svg5-dev qtxmlpatterns5-dev-tools libqt5opengl5-dev
  libopenmpi-dev openmpi-bin libutfcpp-dev libboost-dev libexpat1-dev libfreetype-dev libgdal-dev
  libgl2ps-dev libglew-dev libhdf5-mpi-dev libjpeg-dev liblz4-dev liblzma-dev libxml2-dev
  libnetcdf-dev libpng-dev libpython3-dev libtheora-dev libtiff-dev libx11-dev libgl-dev
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev libdouble-conversion-dev
)

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${#missing[@]} Debian packages: ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The default collection's meshes are libcgal-demo's data.tar.gz under
# /usr/share/doc. Images that drop /usr/share/doc (a dpkg path-exclude, as
# in slim containers) install the package without it: then unpack the
# package itself where Data/cgal-quadrupeds/collection.json also looks.
cgal_archive=/usr/share/doc/libcgal-dev/data.tar.gz
cgal_fallback=/usr/local/share/consistent-mesh/libcgal-demo
if [ ! -f "$cgal_archive" ] && [ ! -f "$cgal_fallback$cgal_archive" ]; then
  echo "setup: $cgal_archive is missing (documentation excluded?): unpacking libcgal-demo into $cgal_fallback"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  download=$(mktemp -d)
  trap 'rm -rf "$download"' EXIT
  # Slim images may have emptied the package lists too.
  if ! (cd "$download" && apt-get download -qq libcgal-demo); then
    "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
    (cd "$download" && apt-get download -qq libcgal-demo)
  fi
  "${sudo_cmd[@]}" mkdir -p "$cgal_fallback"
  "${sudo_cmd[@]}" dpkg -x "$download"/libcgal-demo_*.deb "$cgal_fallback"
fi

build_dir="${CMP_BUILD_DIR:-build}"
# /usr/bin/python3 sees Debian's ParaView modules; a pyenv shim on PATH does not.
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3
cmake --build "$build_dir"
echo "setup: built in $build_dir"
