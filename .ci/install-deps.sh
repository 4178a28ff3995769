#!/usr/bin/env bash
# Installs Kerf's build dependencies from Debian 12 packages (run as root).
#   .ci/install-deps.sh          what building and running kerf needs
#   .ci/install-deps.sh --tests  plus what the test suite needs (LinuxCNC's rs274 as the
#                                independent interpreter the arc tests compare against; Xvfb
#                                for the window tests; Microsoft's SARIF Multitool from the npm
#                                registry, into /opt/kerf-test-tools, to validate SARIF output;
#                                pre-commit, git and python3-yaml for the CI integration tests;
#                                chromium, the real browser the HTML pages are opened in, with
#                                puppeteer-core to drive it and html-validate, from npm)
# Skips apt entirely when everything is already installed.
set -euo pipefail
packages=(g++ cmake ninja-build make pkg-config dpkg-dev libeigen3-dev libcli11-dev libmuparser-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev
  libvtk9-dev libglfw3-dev libimgui-dev libstb-dev libgl-dev libosmesa6-dev libegl-dev libegl-mesa0 libjs-three)
if [[ "${1:-}" == "--tests" ]]; then
  packages+=(linuxcnc-uspace python3 python3-ezdxf python3-shapely xvfb xauth pre-commit git python3-yaml chromium)
  # Debian's Node.js and npm, unless a Node.js with its own npm is installed already.
  command -v npm > /dev/null || packages+=(nodejs npm)
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

# The SARIF validator the tests use (tests/tools/ci_reports_check.py): a pinned version, installed
# once. npm 11 runs no install scripts unless approved; the package's only one marks its binary
# executable, which is done here.
if [[ "${1:-}" == "--tests" ]]; then
  tools=/opt/kerf-test-tools
  multitool="$tools/node_modules/@microsoft/sarif-multitool-linux/Sarif.Multitool"
  if [[ ! -x "$multitool" ]]; then
    mkdir -p "$tools"
    npm install --prefix "$tools" --no-audit --no-fund --loglevel=error @microsoft/sarif-multitool@5.7.0
    chmod u+x "$multitool"
  fi
  # The browser tests (tests/browser): puppeteer-core drives Debian's chromium (it downloads no
  # browser), html-validate checks the pages. Versions that run on Debian 12's Node.js 18.
  if [[ ! -d "$tools/node_modules/puppeteer-core" || ! -d "$tools/node_modules/html-validate" ]]; then
    npm install --prefix "$tools" --no-audit --no-fund --loglevel=error puppeteer-core@24.43.1 html-validate@9.7.1
  fi
fi
