#!/usr/bin/env bash
# Installs Tessera's build and test dependencies from Debian packages.
# Idempotent: packages already present are left alone and apt is not called at all
# when everything is installed.
set -euo pipefail

packages=(
  build-essential cmake ccache pkg-config
  libcgal-dev libboost-dev libeigen3-dev libgmp-dev libmpfr-dev libtbb-dev
  libtet1.5-dev libsuitesparse-dev libopenblas-dev
  catch2 libcli11-dev nlohmann-json3-dev
  libcairo2-dev libopencv-core-dev libopencv-imgproc-dev libopencv-imgcodecs-dev
  clang libclang-rt-14-dev clang-format
  python3 python3-jsonschema
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "tessera: all dependencies already installed"
  exit 0
fi

echo "tessera: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
