#!/usr/bin/env bash
# Installs what ShadowLab needs from Debian/Ubuntu packages (only what is missing), then
# configures and builds it. Sourced by run.sh and test.sh; safe to run again.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
preset="${SHADOWLAB_PRESET:-release}"

packages=(
    cmake ninja-build g++ pkg-config
    qt6-base-dev qt6-base-private-dev libqt6opengl6-dev qt6-charts-dev
    libglm-dev libgl-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libembree-dev libassimp-dev
    qt6-image-formats-plugins   # models' TGA, TIFF and WebP textures (Qt reads them only through these plugins)
    fonts-dejavu-core
    python3            # scripts: the generated test mesh, the speed guard, the damaged-model survey,
                       # the man page, completion and docs made from the program's help
    assimp-testmodels  # test data: real and deliberately broken models
    librsvg2-bin       # install: the icon's PNG sizes, drawn from its SVG at build time
    desktop-file-utils appstream  # install test: the desktop entry's and the metainfo's validators
    dpkg-dev file      # scripts/package.sh: CPack's .deb and its dependencies (dpkg-shlibdeps)
    chromium           # report test: the HTML report opened, printed and pictured headless
    parallel           # scripts/benchmark.sh --jobs: its reports, or their shares, N at a time
    xvfb xauth         # stop-signal test: the explorer on a virtual display, stopped by SIGTERM, SIGINT, SIGHUP
)

# OSMesa is optional (Mesa 25.1 removed it): the headless platform uses EGL, and OSMesa as well
# where the distribution still has it.
if apt-cache show libosmesa6-dev >/dev/null 2>&1; then
    packages+=(libosmesa6-dev)
fi

# The fuzz preset builds with clang and links libFuzzer (scripts/fuzz.sh).
if [ "$preset" = fuzz ]; then
    packages+=(clang libclang-rt-14-dev)
fi

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
    echo "==> installing: ${missing[*]}"
    sudo_cmd=()
    [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
    "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q
    "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

echo "==> configuring and building (preset $preset)"
cd "$root"  # presets are read from the working directory
cmake --preset "$preset" >/dev/null
# SHADOWLAB_BUILD_TARGET builds one target and what it needs (scripts/test.sh --sanitize-quick).
cmake --build --preset "$preset" -j "$(nproc)" ${SHADOWLAB_BUILD_TARGET:+--target "$SHADOWLAB_BUILD_TARGET"}
