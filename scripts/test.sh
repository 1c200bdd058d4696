#!/usr/bin/env bash
# Set up, build and run the whole test suite (Qt Test through CTest, on the headless platform: EGL, and OSMesa for the platform tests).
#
#   ./scripts/test.sh                   the whole suite on the release build (build/release)
#   ./scripts/test.sh --sanitize        the whole suite on the AddressSanitizer + UndefinedBehaviorSanitizer
#                                       build (build/sanitize), as many tests at a time as there are cores: run
#                                       it before resolving a change that touches memory handling
#   ./scripts/test.sh --sanitize-quick  the part CI runs on the sanitizer build too (label sanitize-quick:
#                                       the pure tier, the import worker, settings, the command line), built
#                                       with only what it needs
#
# Further arguments go to ctest (-R NAME, -L LABEL, -j N).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
preset="${SHADOWLAB_PRESET:-release}"
ctest_options=()
case "${1:-}" in
    --sanitize) preset=sanitize; shift; ctest_options=(-j "$(nproc)") ;;
    --sanitize-quick) preset=sanitize; shift; ctest_options=(-j "$(nproc)" -L sanitize-quick); export SHADOWLAB_BUILD_TARGET=sanitize_quick_tests ;;
esac
SHADOWLAB_PRESET="$preset" "$root/scripts/setup.sh"
cd "$root"
ctest --preset "$preset" "${ctest_options[@]}" "$@"
