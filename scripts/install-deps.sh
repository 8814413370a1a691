#!/usr/bin/env bash
# Installs Tessera's build and test dependencies from Debian packages, and the pinned three.js of
# web/package-lock.json (which `tessera view` inlines into its pages) with `npm ci`.
# Idempotent: packages already present are left alone, apt is not called at all when everything is
# installed, and npm only when web/node_modules does not hold the locked version.
set -euo pipefail

packages=(
  build-essential cmake ccache pkg-config
  libcgal-dev libboost-dev libeigen3-dev libgmp-dev libmpfr-dev libtbb-dev
  libtet1.5-dev libsuitesparse-dev libopenblas-dev libjemalloc-dev
  catch2 libcli11-dev nlohmann-json3-dev
  libcairo2-dev libopencv-core-dev libopencv-imgproc-dev libopencv-imgcodecs-dev
  clang libclang-rt-14-dev clang-format
  python3 python3-jsonschema
  chromium
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
# npm from Debian's package unless one is already installed (nodejs from NodeSource ships its own,
# which Debian's npm package conflicts with).
if ! command -v npm >/dev/null; then missing+=(npm); fi

if [ ${#missing[@]} -eq 0 ]; then
  echo "tessera: all Debian packages already installed"
else
  echo "tessera: installing ${missing[*]}"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# three.js for `tessera view`, the exact version of web/package-lock.json (CMake embeds it).
web="$(cd "$(dirname "$0")/.." && pwd)/web"
locked=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["packages"]["node_modules/three"]["version"])' "$web/package-lock.json")
installed=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["version"])' "$web/node_modules/three/package.json" 2>/dev/null || true)
if [ "$locked" = "$installed" ]; then
  echo "tessera: three.js $locked already installed in web/node_modules"
else
  echo "tessera: installing three.js $locked into web/node_modules"
  (cd "$web" && npm ci --no-audit --no-fund)
fi
