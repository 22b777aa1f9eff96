#!/usr/bin/env bash
# Installs what hemiroll needs from Debian's packages, once and quietly.
# Called by `make play`, `make test`, `make build` and `make bench`; does
# nothing when everything is already there. `--fuzz` adds what `make fuzz`
# needs besides: clang with its libFuzzer and sanitizer runtimes. `--slurm`
# adds a Slurm cluster's daemons and munge, for tools/slurm-local.sh (the
# heavy test of `hemiroll sweep --slurm`); nothing else needs them.
# `--peers` adds MuJoCo, Bullet and ODE for tools/peers (peer_bench, called
# by `make test` and `make bench`); the engine and the game never link them.
set -euo pipefail

packages=(
  g++ cmake ninja-build pkg-config make
  libeigen3-dev liblua5.4-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libsundials-dev libboost-dev gnuplot-nox
  nlohmann-json3-dev
  libsdl2-dev
  libepoxy-dev libassimp-dev libstb-dev
  xvfb xauth libgl1-mesa-dri libglx-mesa0 libegl-mesa0
  libimgui-dev libsqlite3-dev
  libfftw3-dev
  libexpat1-dev
)
if [ "${1:-}" = "--fuzz" ]; then
  packages+=(clang libclang-rt-14-dev)
fi
if [ "${1:-}" = "--slurm" ]; then
  packages+=(slurm-wlm munge)
fi
if [ "${1:-}" = "--peers" ]; then
  packages+=(libmujoco-dev libbullet-dev libode-dev)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "hemiroll: installing missing Debian packages: ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    sudo="sudo"
  else
    echo "hemiroll: not root and no sudo; as root run: apt-get install ${missing[*]}" >&2
    exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
