#!/usr/bin/env bash
# Installs Kerf's build dependencies from Debian 12 packages (run as root).
#   .ci/install-deps.sh          what building and running kerf needs
#   .ci/install-deps.sh --tests  plus what the test suite needs (LinuxCNC's rs274 as the
#                                independent interpreter the arc tests compare against; Xvfb
#                                for the window tests)
# Skips apt entirely when everything is already installed.
set -euo pipefail
packages=(g++ cmake make pkg-config libeigen3-dev libcli11-dev libmuparser-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev
  libvtk9-dev libglfw3-dev libimgui-dev libstb-dev libgl-dev libosmesa6-dev libegl-dev libegl-mesa0)
if [[ "${1:-}" == "--tests" ]]; then
  packages+=(linuxcnc-uspace python3 python3-ezdxf python3-shapely xvfb xauth)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
