#!/usr/bin/env bash
# Set up, build and start ShadowLab on the built-in default scene.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh"
binary="$root/build/${SHADOWLAB_PRESET:-release}/app/shadowlab"
if [ -z "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
    # No display: the explorer window rendered offscreen, then the scene and its shadow map.
    "$binary" screenshot --scene seed --out "$root/shadowlab-window.png" "$@"
    exec "$binary" render --scene seed --out "$root/shadowlab-seed.png" --depth-out "$root/shadowlab-seed-depth.png" "$@"
fi
exec "$binary" "$@"
