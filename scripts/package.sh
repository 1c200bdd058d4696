#!/usr/bin/env bash
# Builds ShadowLab's Debian package with CPack (packaging/CMakeLists.txt): the release build
# under /usr, depending on the packages dpkg-shlibdeps finds for its libraries. Sets up and
# builds first (setup.sh); prints the package's path.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh"
build="$root/build/${SHADOWLAB_PRESET:-release}"
rm -f "$build"/package/*.deb
cpack --config "$build/CPackConfig.cmake" -B "$build/package" >/dev/null
ls "$build"/package/*.deb
