#!/bin/bash
# Installs the physics engines the work-precision benchmark compares against
# (Debian bookworm: MuJoCo 2.2.2, Bullet 3.24, ODE 0.16). The benchmark builds
# without them and skips their lines; this script is only for a full run.
# Skips apt entirely when everything is already there.
set -euo pipefail
packages=(libmujoco-dev libbullet-dev libode-dev pkg-config)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  echo "install_bench_deps: installing ${missing[*]}"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
