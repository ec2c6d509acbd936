#!/usr/bin/env bash
# Installs, from Debian 12's packages, whatever cosph needs and this machine
# lacks. Does nothing when everything is there. Uses sudo when not root.
set -euo pipefail

packages=(
  build-essential cmake ccache pkg-config
  libzmq3-dev cppzmq-dev
  libprotobuf-dev protobuf-compiler
  libeigen3-dev libhdf5-dev libgtest-dev libtbb-dev
  python3-numpy python3-matplotlib python3-h5py python3-meshio
  python3-pil  # coupler/cosph plot --movie writes a GIF with it when ffmpeg is absent
)

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$package")
done
if ((${#missing[@]} == 0)); then
  echo "install_deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install_deps: installing ${missing[*]}"
sudo=""
if ((EUID != 0)); then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
