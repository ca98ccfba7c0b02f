#!/usr/bin/env bash
# Installs every build, test and benchmark dependency from Debian's packages; with --fuzz also clang and
# libFuzzer (in Debian's compiler-rt package) for scripts/fuzz.sh. Idempotent: a second run only checks
# that the packages are present.
set -euo pipefail
packages=(
  build-essential cmake ccache pkg-config
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev libeigen3-dev
  doctest-dev gemmi-dev tao-pegtl-dev zlib1g-dev libtbb-dev libcli11-dev nlohmann-json3-dev
  voronota time
  python3-dev pybind11-dev python3-numpy python3-pytest python3-pip python3-setuptools python3-wheel
  python3-matplotlib
)
if [ "${1:-}" = "--fuzz" ]; then packages+=(clang libclang-rt-dev); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "install-deps: installed ${missing[*]}"
