#!/usr/bin/env bash
# gpu-bundle.sh: builds ShadowLab without OSMesa (build/gpu) and packs the binaries and the shared
# libraries they need into one folder for a bare x86-64 Linux GPU machine (glibc >= 2.36, NVIDIA
# driver, no display). OUT/run.sh runs the GL tests, `shadowlab render` and `shadowlab bench` there
# on EGL (device platform by default) and collects logs, PNGs, JSON and a summary.
#
#   scripts/gpu-bundle.sh [OUT=build/gpu-bundle]   # OUT relative to $PWD; then, on the GPU machine:
#   OUT/run.sh                                     # see its header for knobs and outputs
# Build: cmake -S . -B build/gpu -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADOWLAB_WITH_OSMESA=OFF,
# then only the bundled targets, -j2. The script stops if a bundled binary still links OSMesa.
#
# Contents (MANIFEST.txt: every file, its origin, what was left out and why):
#   bin/      shadowlab, shadowlab-import-worker and the GL tests, stripped
#   lib/      their DT_NEEDED closure minus what the GPU machine brings: glibc; the glvnd GL/EGL
#             dispatch libraries (libEGL, libGLX, libGLdispatch, libOpenGL: the NVIDIA driver
#             installs them); Mesa, and whatever only Mesa would pull in (the walk stops there)
#   lib/cxx/  libstdc++ and libgcc_s; run.sh puts them on the path only when the machine's own
#             libstdc++ lacks a GLIBCXX/CXXABI version the bundle needs
#   plugins/imageformats/libqjpeg.so (PNG is built into QtGui; the headless platform is linked in)
#   fonts/    DejaVuSans.ttf with a private fonts.conf, so text renders as it does here
#
# Size: unpacked the payload is ~135 MiB (Embree and ICU alone are over 70 MiB), so bin/ lib/
# plugins/ fonts/ are shipped as payload.tar.xz; the 60 MiB limit is met by that compressed
# bundle, not by the unpacked files. run.sh unpacks it on first use into
# ${BUNDLE_UNPACK_DIR:-${TMPDIR:-/tmp}/shadowlab-gpu-bundle-<checksum>}.
set -euo pipefail

out=${1:-build/gpu-bundle}
limit_mib=60
gl_tests=(tst_HeadlessPlatform tst_Shadows tst_LightTypes tst_FilterableShadows tst_SoftShadows tst_Accuracy)
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build=$root/build/gpu

die() { echo "gpu-bundle.sh: $*" >&2; exit 1; }
note() { echo "==> $*"; }
for tool in cmake ninja ldd readelf strip objdump tar xz cksum; do command -v "$tool" >/dev/null || die "needs $tool"; done
case "$out" in /|"$root"|.|"") die "refusing OUT='$out'" ;; esac

# --- build ----------------------------------------------------------------------------------
note "configuring and building $build (SHADOWLAB_WITH_OSMESA=OFF)"
(cd "$root" &&
    cmake -S . -B build/gpu -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADOWLAB_WITH_OSMESA=OFF &&
    cmake --build build/gpu --target shadowlab shadowlab-import-worker "${gl_tests[@]}" -j2)
sources=("$build/app/shadowlab" "$build/app/shadowlab-import-worker")
for t in "${gl_tests[@]}"; do sources+=("$build/tests/$t"); done
for f in "${sources[@]}"; do
    [ -x "$f" ] || die "the build made no $f"
    ! ldd "$f" | grep -i osmesa || die "$f still links OSMesa with SHADOWLAB_WITH_OSMESA=OFF"
done

rm -rf "$out"
mkdir -p "$out/bin" "$out/lib/cxx" "$out/plugins/imageformats" "$out/fonts"
out=$(cd "$out" && pwd)
strip_copy() { strip --strip-unneeded -o "$2" "$1" 2>/dev/null || cp -L "$1" "$2"; chmod u+w "$2"; }

note "binaries -> $out/bin"
for f in "${sources[@]}"; do strip_copy "$f" "$out/bin/$(basename "$f")"; done
qt_plugins=$(qtpaths6 --query QT_INSTALL_PLUGINS 2>/dev/null || echo /usr/lib/x86_64-linux-gnu/qt6/plugins)
jpeg=$qt_plugins/imageformats/libqjpeg.so; [ -f "$jpeg" ] || die "no $jpeg"
strip_copy "$jpeg" "$out/plugins/imageformats/libqjpeg.so"
font=$(fc-match -f '%{file}' 'DejaVu Sans' 2>/dev/null || true)
[ -f "$font" ] || font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf; [ -f "$font" ] || die "no DejaVuSans.ttf"
cp -L "$font" "$out/fonts/DejaVuSans.ttf"

# --- libraries: walk DT_NEEDED, resolved with ldd, not descending into what is left out ---------
exclusion() {
    case "$1" in
        linux-vdso.so.*|ld-linux*.so.*|libc.so.*|libm.so.*|libmvec.so.*|libpthread.so.*|libdl.so.*|librt.so.*|\
        libresolv.so.*|libutil.so.*|libanl.so.*|libnsl.so.*|libnss_*|libthread_db.so.*)
            echo "glibc: the machine's own (glibc >= 2.36)" ;;
        libGL.so.*|libEGL.so.*|libGLX.so.*|libGLdispatch.so.*|libOpenGL.so.*|libGLESv1_CM.so.*|libGLESv2.so.*)
            echo "glvnd GL/EGL dispatch: installed with the NVIDIA driver" ;;
        libOSMesa.so.*|libglapi.so.*|libgbm.so.*|libdrm*.so.*|libEGL_mesa.so.*|libGLX_mesa.so.*|*_dri.so|libgallium*|libLLVM*)
            echo "Mesa: the GPU machine renders through the NVIDIA driver" ;;
    esac
}
declare -A where=() bundled=() excluded=()
needed_of() { readelf -dW "$1" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'; }
queue=()
for f in "${sources[@]}" "$jpeg"; do
    while read -r name arrow path _; do
        [ "$arrow" = "=>" ] || continue
        [ "$path" != not ] || die "ldd $f: $name not found"
        where[$name]=$path
    done < <(ldd "$f")
    mapfile -t -O "${#queue[@]}" queue < <(needed_of "$f")
done
while [ ${#queue[@]} -gt 0 ]; do
    name=${queue[0]}; queue=("${queue[@]:1}")
    [ -z "${bundled[$name]:-}${excluded[$name]:-}" ] || continue
    reason=$(exclusion "$name")
    if [ -n "$reason" ]; then excluded[$name]=$reason; continue; fi
    [ -n "${where[$name]:-}" ] || die "cannot resolve $name"
    case "$name" in libstdc++.so.*|libgcc_s.so.*) bundled[$name]=lib/cxx ;; *) bundled[$name]=lib ;; esac
    mapfile -t -O "${#queue[@]}" queue < <(needed_of "${where[$name]}")
done
for name in "${!where[@]}"; do   # resolved by ldd, never reached: only needed by something left out
    [ -z "${bundled[$name]:-}${excluded[$name]:-}" ] || continue
    reason=$(exclusion "$name"); excluded[$name]=${reason:-"needed only by libraries left out"}
done
note "copying ${#bundled[@]} libraries -> $out/lib"
for name in "${!bundled[@]}"; do strip_copy "${where[$name]}" "$out/${bundled[$name]}/$name"; done

# newest symbol version matching $1 that the bundle uses (lib/cxx left out: it defines them all)
versions() { find "$out/bin" "$out/lib" "$out/plugins" -path "$out/lib/cxx" -prune -o -type f -print0 |
    xargs -0 objdump -T 2>/dev/null | grep -o "$1[0-9.]*" | sort -uV | tail -n 1; }
source_id="$(git -C "$root" describe --always --dirty 2>/dev/null || echo unknown) $(date -u +%FT%TZ)"
{
    echo "ShadowLab GPU bundle from build/gpu (SHADOWLAB_WITH_OSMESA=OFF), $source_id"
    echo "needs: glibc >= $(versions 'GLIBC_2\.' | sed 's/GLIBC_//'), the NVIDIA driver (libEGL, libGLX, libOpenGL, libGLdispatch, EGL vendor library)"
    echo "tests: ${gl_tests[*]}"
    echo "not bundled: tst_ImportWorker: it runs tests/fake-import-worker from the absolute build path"
    echo "  compiled into it, which does not exist on the GPU machine; it needs no GPU, so it runs here."
    echo; echo "== bundled (size, file, from)"
    for name in $(printf '%s\n' "${!bundled[@]}" | sort); do
        printf '%10s  %-30s %s\n' "$(stat -c %s "$out/${bundled[$name]}/$name")" "${bundled[$name]}/$name" "${where[$name]}"
    done
    for f in "$out"/bin/* "$out/plugins/imageformats/libqjpeg.so" "$out/fonts/DejaVuSans.ttf"; do
        printf '%10s  %s\n' "$(stat -c %s "$f")" "${f#"$out"/}"
    done
    echo; echo "== left out (name: why)"
    for name in $(printf '%s\n' "${!excluded[@]}" | sort); do echo "$name: ${excluded[$name]}"; done
} > "$out/MANIFEST.txt"
{
    echo "BUNDLE_TESTS='${gl_tests[*]}'"
    echo "BUNDLE_REQ_GLIBCXX='$(versions 'GLIBCXX_3\.')'"
    echo "BUNDLE_REQ_CXXABI='$(versions 'CXXABI_1\.')'"
    echo "BUNDLE_SOURCE='$source_id'"
} > "$out/bundle.env"

# --- run.sh ---------------------------------------------------------------------------------
cat > "$out/run.sh" <<'RUN'
#!/usr/bin/env bash
# run.sh (written by scripts/gpu-bundle.sh): ShadowLab's GL tests, renders and benchmarks from
# this bundle on a GPU machine with no display (Qt's headless platform, EGL). Keeps going after a
# failure; writes under ${OUT_DIR:-./results}: summary.txt (PASS/FAIL/TIMEOUT per step, GPU,
# renderer), env.txt, tst_*.log + tst_*.junit.xml, render-<scene>.png + -depth.png + .log,
# bench-<scene>-<profile>.json + .log, bench-seed-<variant>.json + .log. Exit status 0 when every step passed.
#   ./run.sh                     everything
#   ./run.sh exec CMD [ARG...]   CMD in the same environment (bin/ first on PATH)
# Knobs: OUT_DIR=./results  RUN_TESTS="<all bundled>" ("" runs none)  TEST_TIMEOUT=300
#   SCENES="seed city" ("" skips renders and benches)  PROFILES="hardware software" (rasteriser.profile of each scene's bench)  SIZE=1920x1080  STEP_TIMEOUT=300 (each render/bench)
#   VARIANTS="point:light.type=point vsm:filter.mode=vsm spot:light.type=spot" (seed, light moving; "" skips)
#   SHADOWLAB_EGL_PLATFORM=device (surfaceless: Mesa's software EGL; empty: surfaceless, then device)
#   BUNDLE_UNPACK_DIR: where payload.tar.xz is unpacked
set -uo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=/dev/null
. "$here/bundle.env"
root=${BUNDLE_UNPACK_DIR:-${TMPDIR:-/tmp}/shadowlab-gpu-bundle-$BUNDLE_PAYLOAD_ID}
if [ ! -f "$root/.unpacked" ]; then
    echo "run.sh: unpacking payload.tar.xz into $root" >&2
    mkdir -p "$root" && tar -xJf "$here/payload.tar.xz" -C "$root" && touch "$root/.unpacked" || exit 2
fi

# libstdc++/libgcc_s: the machine's pair when its libstdc++ has every version the bundle needs.
sys_cxx=$({ ldconfig -p || /sbin/ldconfig -p; } 2>/dev/null | awk '$1 == "libstdc++.so.6" && /x86-64/ {print $NF; exit}')
if [ -n "$sys_cxx" ] && grep -aqF "$BUNDLE_REQ_GLIBCXX" "$sys_cxx" && grep -aqF "$BUNDLE_REQ_CXXABI" "$sys_cxx"; then
    cxx_note="the machine's ($sys_cxx)"; ld_path=$root/lib
else
    cxx_note="bundled (lib/cxx)"; ld_path=$root/lib/cxx:$root/lib
fi
export LD_LIBRARY_PATH=$ld_path${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
export QT_PLUGIN_PATH=$root/plugins
export QT_QPA_PLATFORM=${QT_QPA_PLATFORM:-headless}
export SHADOWLAB_EGL_PLATFORM=${SHADOWLAB_EGL_PLATFORM-device}
export SHADOWLAB_IMPORT_WORKER=$root/bin/shadowlab-import-worker
export PATH=$root/bin:$PATH
# glvnd finds no EGL vendor without a vendor file; write one where libEGL_nvidia is there but its file is not.
vendor_note="glvnd's vendor folders"
if [ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ] && ! grep -qsl nvidia /etc/glvnd/egl_vendor.d/*.json /usr/share/glvnd/egl_vendor.d/*.json; then
    nvidia_egl=$({ ldconfig -p || /sbin/ldconfig -p; } 2>/dev/null | awk '$1 == "libEGL_nvidia.so.0" {print $NF; exit}')
    vendor_note="no nvidia EGL vendor file, no libEGL_nvidia.so.0"
    if [ -n "$nvidia_egl" ]; then
        vendor_file=${TMPDIR:-/tmp}/shadowlab-egl-vendor-$(id -u).json
        printf '{ "file_format_version" : "1.0.0", "ICD" : { "library_path" : "%s" } }\n' "$nvidia_egl" > "$vendor_file"
        export __EGL_VENDOR_LIBRARY_FILENAMES=$vendor_file
        vendor_note="written: $vendor_file"
    fi
fi
fc_dir=${TMPDIR:-/tmp}/shadowlab-fontconfig-$(id -u)
mkdir -p "$fc_dir"
cat > "$fc_dir/fonts.conf" <<FONTS
<?xml version="1.0"?>
<!DOCTYPE fontconfig SYSTEM "fonts.dtd">
<fontconfig>
  <dir>$root/fonts</dir>
  <cachedir>$fc_dir/cache</cachedir>
  <match target="font">
    <edit name="antialias" mode="assign"><bool>true</bool></edit>
    <edit name="hinting" mode="assign"><bool>true</bool></edit>
    <edit name="hintstyle" mode="assign"><const>hintslight</const></edit>
    <edit name="lcdfilter" mode="assign"><const>lcddefault</const></edit>
  </match>
</fontconfig>
FONTS
export FONTCONFIG_FILE=$fc_dir/fonts.conf
if [ "${1:-}" = exec ]; then shift; exec "$@"; fi

results=${OUT_DIR:-./results}
mkdir -p "$results/work" && results=$(cd "$results" && pwd) || exit 2
summary=$results/summary.txt
failures=0
say() { echo "$*" | tee -a "$summary"; }
record() {   # record NAME RC SECONDS [DETAIL]
    local status=FAIL
    case "$2" in 0) status=PASS ;; 124|137) status=TIMEOUT ;; esac
    [ "$status" = PASS ] || failures=$((failures + 1))
    say "$(printf '%-8s %-24s %5ss  %s' "$status" "$1" "$3" "${4:-}")"
}
: > "$summary"
say "ShadowLab GPU bundle ($BUNDLE_SOURCE) on $(uname -n), $(date -u +%FT%TZ)"
if command -v nvidia-smi >/dev/null; then nvidia-smi -L 2>&1; else echo "(no nvidia-smi)"; fi | sed 's/^/  /' | tee -a "$summary"
say "  glibc $(getconf GNU_LIBC_VERSION | awk '{print $2}'); libstdc++: $cxx_note; EGL vendors: $vendor_note; SHADOWLAB_EGL_PLATFORM=${SHADOWLAB_EGL_PLATFORM:-<empty>}"
{
    echo "LD_LIBRARY_PATH=$LD_LIBRARY_PATH"
    { ldconfig -p || /sbin/ldconfig -p; } 2>/dev/null | grep -E 'lib(EGL|GLX|OpenGL|GLdispatch|nvidia-egl|nvidia-glcore)' || echo "(no GL libraries in the loader cache)"
    ls -l /etc/glvnd/egl_vendor.d /usr/share/glvnd/egl_vendor.d 2>&1
    cat /proc/driver/nvidia/version 2>/dev/null
    ldd "$root/bin/shadowlab" 2>&1
} > "$results/env.txt"
! grep -q 'not found' "$results/env.txt" || say "  WARNING: unresolved libraries, see env.txt"

step() {   # step TIMEOUT OUT ERR CMD...: CMD in work/ under timeout (ERR "": into OUT); sets rc, secs
    local limit=$1 o=$2 e=${3:-/dev/stdout} start; shift 3
    start=$(date +%s)
    (cd "$results/work" && timeout -k 10 "$limit" "$@") > "$o" 2> "$e"
    rc=$?; secs=$(( $(date +%s) - start ))
}
run_test() {
    local log=$results/$1.log
    step "${TEST_TIMEOUT:-300}" "$log" "" "$root/bin/$1" -o "$results/$1.junit.xml,junitxml" -o -,txt
    record "$1" "$rc" "$secs" "$(grep -m1 '^Totals:' "$log" || tail -n 1 "$log")"
    [ "$1" != tst_HeadlessPlatform ] || grep -m1 -o 'GL_RENDERER: .*' "$log" | sed 's/^/  /' | tee -a "$summary"
}
tests=${RUN_TESTS-$BUNDLE_TESTS}
# tst_HeadlessPlatform first (is there a GL 3.3 core context, and whose), then renders, benches, tests.
case " $tests " in *" tst_HeadlessPlatform "*) run_test tst_HeadlessPlatform ;; esac
for scene in ${SCENES-seed city}; do
    png=$results/render-$scene.png
    step "${STEP_TIMEOUT:-300}" "$results/render-$scene.log" "" "$root/bin/shadowlab" render --scene "$scene" \
        --size "${SIZE:-1920x1080}" --out "$png" --depth-out "$results/render-$scene-depth.png"
    [ "$rc" != 0 ] || [ -s "$png" ] || rc=1
    record "render $scene" "$rc" "$secs" "render-$scene.png"
    # Both rasteriser profiles: whether a software rasteriser's optimisations pay on this GPU.
    for profile in ${PROFILES-hardware software}; do
        json=$results/bench-$scene-$profile.json
        step "${STEP_TIMEOUT:-300}" "$json" "$results/bench-$scene-$profile.log" "$root/bin/shadowlab" bench --json \
            --scene "$scene" --size "${SIZE:-1920x1080}" --set "rasteriser.profile=$profile"
        [ "$rc" != 0 ] || head -c 1 "$json" | grep -q '{' || rc=1
        renderer=$(sed -n 's/^ *"renderer": "\(.*\)",*$/\1/p' "$json" | head -n 1)
        record "bench $scene ($profile profile)" "$rc" "$secs" "${renderer:+renderer: $renderer}"
    done
done
# The point light and a moment technique with the light moving: their times beside the counts
# (draws, primitives, samples, texels cleared, blur bytes, taps) that bench --json gives for any GPU.
for variant in ${VARIANTS-point:light.type=point vsm:filter.mode=vsm spot:light.type=spot}; do
    json=$results/bench-seed-${variant%%:*}.json
    step "${STEP_TIMEOUT:-300}" "$json" "$results/bench-seed-${variant%%:*}.log" "$root/bin/shadowlab" bench --json \
        --scene seed --phase moving-light --size "${SIZE:-1920x1080}" --set "${variant#*:}"
    [ "$rc" != 0 ] || head -c 1 "$json" | grep -q '{' || rc=1
    record "bench seed ${variant#*:}" "$rc" "$secs" "bench-seed-${variant%%:*}.json (times and counts)"
done
for t in $tests; do [ "$t" = tst_HeadlessPlatform ] || run_test "$t"; done
say "overall: $failures step(s) failed; results in $results"
[ "$failures" = 0 ]
RUN
chmod +x "$out/run.sh"

# --- pack -----------------------------------------------------------------------------------
note "unpacked: $(du -sh "$out" | cut -f1); packing into payload.tar.xz (xz -6 -T2, a minute or two)"
tar -C "$out" -cf - bin lib plugins fonts | xz -6 -T2 > "$out/payload.tar.xz"
(cd "$out" && rm -rf bin lib plugins fonts)
echo "BUNDLE_PAYLOAD_ID='$(cksum < "$out/payload.tar.xz" | cut -d' ' -f1)'" >> "$out/bundle.env"
note "bundle: $out, $(du -sh "$out" | cut -f1)"
[ "$(du -sk "$out" | cut -f1)" -le $((limit_mib * 1024)) ] || die "over $limit_mib MiB"
