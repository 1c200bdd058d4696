#!/usr/bin/env bash
# gpu-bundle.sh: packs the built ShadowLab binaries and the shared libraries they need into ONE
# self-contained folder for a bare x86-64 Linux GPU machine (glibc >= 2.36, NVIDIA driver, no
# display), and writes OUT/run.sh, which runs the GL tests, `shadowlab render` and `shadowlab bench`
# there on EGL's device platform and collects logs, JSON, PNGs and a summary. Builds nothing.
#
#   scripts/gpu-bundle.sh [BUILD_DIR=build/release] [OUT=build/gpu-bundle]
#   # copy OUT to the GPU machine, then there:
#   OUT/run.sh                          # everything; results in ${OUT_DIR:-./results}
#   OUT/run.sh exec shadowlab --version # one command in the bundle's environment
#   (OUT/run.sh's header lists the knobs: RUN_TESTS, BENCH_SCENES, RENDER_SCENES, ...)
#
# What goes in (relative paths are taken from the current folder):
#   bin/      shadowlab, shadowlab-import-worker, the GL-offscreen tests, tst_ImportWorker and its
#             fake-import-worker, stripped (--strip-unneeded; the build has debug info)
#   lib/      every library they load: the DT_NEEDED graph from the binaries, resolved with ldd,
#             minus what the target machine brings: glibc, the glvnd GL/EGL dispatch libraries
#             (libGL, libEGL, libGLX, libGLdispatch, libOpenGL: the NVIDIA driver installs them)
#             and all of Mesa (OSMesa, glapi, gbm, drm, LLVM, and what only they pull in)
#   lib/cxx/  libstdc++ and libgcc_s (GCC 12); run.sh uses them unless the machine's own
#             libstdc++ has every GLIBCXX/CXXABI version the bundle needs
#   lib-glvnd-fallback/  Debian's glvnd libraries, NOT on the library path unless a binary
#             cannot find libEGL.so.1 & co. on the machine (GLVND_FALLBACK=0 leaves them out)
#   plugins/  Qt's imageformats/libqjpeg.so (PNG is built into QtGui); the headless platform
#             plugin is linked into the binaries
#   fonts/    DejaVuSans.ttf, so text (the depth view's legend) renders as it does here
#   bundle.env, MANIFEST.txt  what run.sh needs to know; what was bundled, left out and why
#
# OSMesa: the binaries link libOSMesa.so.8 (the software fallback backend), which needs libLLVM
# (110 MiB) and libz3. The copies in bin/ have that DT_NEEDED entry removed in place; their six
# OSMesa* functions are reached only through lazily bound PLT slots. Five are called only by the
# OSMesa backend, which run.sh rules out (SHADOWLAB_HEADLESS=egl); the sixth,
# OSMesaGetCurrentContext, is also asked by the surfaces' destructors, so its reference is renamed
# glXGetCurrentContext (no argument, NULL with no GLX context current). Binaries linked with
# BIND_NOW or binding an OSMesa symbol at load time stop the script. A build configured with
# -DSHADOWLAB_WITH_OSMESA=OFF does not link OSMesa and is copied as it is.
#
# Size: if bin/ lib/ ... together exceed LIMIT_MIB (default 60), they are packed into
# OUT/payload.tar.xz (PACK=auto; PACK=always|never to force), and run.sh unpacks it on first use
# into ${BUNDLE_UNPACK_DIR:-${TMPDIR:-/tmp}/shadowlab-gpu-bundle-<id>}, so OUT stays small.
set -euo pipefail

build_dir=${1:-build/release}
out=${2:-build/gpu-bundle}
limit_mib=${LIMIT_MIB:-60}
pack=${PACK:-auto}
glvnd_fallback=${GLVND_FALLBACK:-1}
drop_needed=(libOSMesa.so.8)
gl_tests=(tst_HeadlessPlatform tst_Shadows tst_LightTypes tst_FilterableShadows tst_SoftShadows tst_Accuracy)
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

die() { echo "gpu-bundle.sh: $*" >&2; exit 1; }
note() { echo "==> $*"; }
case "$pack" in auto|always|never) ;; *) die "PACK must be auto, always or never" ;; esac
for tool in ldd readelf strip strings objdump python3 tar xz cksum; do
    command -v "$tool" >/dev/null || die "needs $tool"
done
[ -x "$build_dir/app/shadowlab" ] || die "no $build_dir/app/shadowlab (build first: scripts/setup.sh)"
[ -x "$build_dir/app/shadowlab-import-worker" ] || die "no $build_dir/app/shadowlab-import-worker"
case "$out" in /|"$root"|.|"") die "refusing OUT='$out'" ;; esac

rm -rf "$out"
mkdir -p "$out/bin" "$out/lib/cxx" "$out/plugins/imageformats" "$out/fonts"
out=$(cd "$out" && pwd)

# --- binaries -------------------------------------------------------------------------------
sources=("$build_dir/app/shadowlab" "$build_dir/app/shadowlab-import-worker")
tests=()
for t in "${gl_tests[@]}" tst_ImportWorker; do
    if [ -x "$build_dir/tests/$t" ]; then
        sources+=("$build_dir/tests/$t"); tests+=("$t")
    else
        echo "warning: $build_dir/tests/$t is missing; not bundled" >&2
    fi
done
fake_worker_path=""
if [[ " ${tests[*]} " == *" tst_ImportWorker "* ]]; then
    [ -x "$build_dir/tests/fake-import-worker" ] || die "tst_ImportWorker needs $build_dir/tests/fake-import-worker"
    sources+=("$build_dir/tests/fake-import-worker")
    # The test calls the fake worker by the absolute path compiled into it (a UTF-16 QStringLiteral).
    fake_worker_path=$(strings -a -el "$build_dir/tests/tst_ImportWorker" | grep -m1 '/fake-import-worker$' || true)
fi

# strip_copy SRC DST: the stripped copy, or a plain copy where stripping gains nothing.
strip_copy() {
    cp -L "$1" "$2.orig"
    if strip --strip-unneeded -o "$2" "$2.orig" 2>/dev/null && [ "$(stat -c %s "$2")" -lt "$(stat -c %s "$2.orig")" ]; then
        rm -f "$2.orig"
    else
        mv -f "$2.orig" "$2"
    fi
    chmod u+w "$2"
}

note "binaries -> $out/bin"
for src in "${sources[@]}"; do
    strip_copy "$src" "$out/bin/$(basename "$src")"
done

# --- libraries ------------------------------------------------------------------------------
# exclusion NAME: why the target machine provides NAME (empty: bundle it).
exclusion() {
    case "$1" in
        linux-vdso.so.*|ld-linux*.so.*|libc.so.*|libm.so.*|libmvec.so.*|libpthread.so.*|libdl.so.*|librt.so.*|\
        libresolv.so.*|libutil.so.*|libanl.so.*|libnsl.so.*|libnss_*|libBrokenLocale.so.*|libthread_db.so.*|libc_malloc_debug.so.*)
            echo "glibc: the machine's own (glibc >= 2.36)" ;;
        libGL.so.*|libEGL.so.*|libGLX.so.*|libGLdispatch.so.*|libOpenGL.so.*|libGLESv1_CM.so.*|libGLESv2.so.*)
            echo "glvnd GL/EGL dispatch: installed with the NVIDIA driver (a copy could mismatch its vendor library)" ;;
        libOSMesa.so.*|libglapi.so.*|libgbm.so.*|libdrm*.so.*|libEGL_mesa.so.*|libGLX_mesa.so.*|*_dri.so|libgallium*|libLLVM*|libxatracker.so.*)
            echo "Mesa: the GPU machine renders through the NVIDIA driver" ;;
        libEGL_nvidia.so.*|libGLX_nvidia.so.*|libnvidia-*|libcuda.so.*)
            echo "NVIDIA driver" ;;
    esac
}

declare -A where=()      # soname -> resolved path (from ldd)
declare -A bundled=()    # soname -> destination folder
declare -A excluded=()   # soname -> reason
declare -A needers=()    # soname -> who needs it
map_ldd() {
    local name arrow path rest
    while read -r name arrow path rest; do
        [ "$arrow" = "=>" ] || continue
        [ "$path" = "not" ] && die "ldd $1: $name not found"
        [ -n "${where[$name]:-}" ] || where[$name]=$path
    done < <(ldd "$1")
}
needed_of() { readelf -dW "$1" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'; }

qt_plugins=/usr/lib/x86_64-linux-gnu/qt6/plugins
qt_plugin_dir=$(qtpaths6 --query QT_INSTALL_PLUGINS 2>/dev/null || true)
[ -d "$qt_plugin_dir/imageformats" ] && qt_plugins=$qt_plugin_dir
plugins=()
for p in libqjpeg.so; do   # PNG is built into QtGui; add more names here
    if [ -f "$qt_plugins/imageformats/$p" ]; then
        strip_copy "$qt_plugins/imageformats/$p" "$out/plugins/imageformats/$p"
        plugins+=("$qt_plugins/imageformats/$p")
    else
        echo "warning: no $qt_plugins/imageformats/$p" >&2
    fi
done

note "walking DT_NEEDED from ${#sources[@]} binaries and ${#plugins[@]} plugin(s)"
queue=()
for f in "${sources[@]}" "${plugins[@]}"; do
    map_ldd "$f"
    for n in $(needed_of "$f"); do queue+=("$n"); needers[$n]+="$(basename "$f") "; done
done
while [ ${#queue[@]} -gt 0 ]; do
    name=${queue[0]}; queue=("${queue[@]:1}")
    [ -n "${bundled[$name]:-}${excluded[$name]:-}" ] && continue
    reason=$(exclusion "$name")
    if [ -n "$reason" ]; then
        excluded[$name]=$reason; continue       # and not what it needs: Mesa's LLVM stays out with it
    fi
    path=${where[$name]:-}
    [ -n "$path" ] || die "cannot resolve $name (needed by ${needers[$name]:-?})"
    case "$name" in libstdc++.so.*|libgcc_s.so.*) dest=lib/cxx ;; *) dest=lib ;; esac
    bundled[$name]=$dest
    for n in $(needed_of "$path"); do queue+=("$n"); needers[$n]+="$name "; done
done
# What ldd listed that the walk never reached: pulled in only through an excluded library.
declare -A only_via=()
for name in "${!where[@]}"; do
    [ -z "${bundled[$name]:-}" ] || continue
    for n in $(needed_of "${where[$name]}"); do
        [ -n "${bundled[$n]:-}${excluded[$n]:-}" ] || only_via[$n]+="$name "
    done
done
for name in "${!only_via[@]}"; do
    reason=$(exclusion "$name")
    if [ -n "$reason" ]; then excluded[$name]=$reason; unset "only_via[$name]"; else only_via[$name]="needed only by ${only_via[$name]}(left out)"; fi
done

note "copying ${#bundled[@]} libraries -> $out/lib"
for name in "${!bundled[@]}"; do
    strip_copy "${where[$name]}" "$out/${bundled[$name]}/$name"
done

if [ "$glvnd_fallback" = 1 ]; then
    mkdir -p "$out/lib-glvnd-fallback"
    for name in libEGL.so.1 libGLX.so.0 libGLdispatch.so.0 libOpenGL.so.0; do
        [ -n "${where[$name]:-}" ] && cp -L "${where[$name]}" "$out/lib-glvnd-fallback/$name"
    done
fi

font=$(fc-match -f '%{file}' 'DejaVu Sans' 2>/dev/null || true)
[ -f "$font" ] || font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
if [ -f "$font" ]; then cp -L "$font" "$out/fonts/"; else echo "warning: no DejaVuSans.ttf; run.sh uses the machine's fonts" >&2; fi

# --- drop libOSMesa.so.8 from the copies' DT_NEEDED -----------------------------------------
# The EGL path still calls one OSMesa function: the surfaces' destructors ask
# OSMesaGetCurrentContext() whether OSMesa draws into the buffer being freed
# (OsMesaOpenGLContext::releaseIfDrawingTo). That reference is renamed, in place, to
# glXGetCurrentContext: glvnd's libGLX (loaded for QtGui) also takes no argument and returns
# NULL unless a GLX context is current, which never happens here. The other five OSMesa*
# functions are called only by the OSMesa backend. A build configured with
# -DSHADOWLAB_WITH_OSMESA=OFF needs none of this: its binaries do not link OSMesa.
redirect=(OSMesaGetCurrentContext=glXGetCurrentContext)
for lib in "${drop_needed[@]}"; do
    lib_path=${where[$lib]:-}
    [ -n "$lib_path" ] || continue
    provided=$(readelf --dyn-syms -W "$lib_path" | awk 'NR>3 && $7!="UND" {sub(/@.*/,"",$8); print $8}' | sort -u)
    for f in "$out"/bin/*; do
        needed_of "$f" | grep -qx "$lib" || continue
        if readelf -dW "$f" | grep -Eq '\(BIND_NOW\)|Flags:.*\bNOW\b'; then
            die "$(basename "$f") is linked with BIND_NOW: removing $lib would make it fail to start"
        fi
        used=$(readelf --dyn-syms -W "$f" | awk '$7=="UND" {sub(/@.*/,"",$8); print $8}' | sort -u | comm -12 - <(echo "$provided"))
        eager=$(readelf -rW "$f" | awk '$3 ~ /^R_X86_64/ && $3 != "R_X86_64_JUMP_SLOT" {sub(/@.*/,"",$5); print $5}' | sort -u | comm -12 - <(echo "$used"))
        [ -z "$eager" ] || die "$(basename "$f") binds ${eager//$'\n'/ } from $lib at load time; cannot drop it"
        renames=()
        for r in "${redirect[@]}"; do
            ! grep -qx "${r%%=*}" <<<"$used" || renames+=("$r")
        done
        python3 - "$f" "$lib" "${renames[@]}" <<'PY'
# ELF64 surgery in place, on argv[1]: removes the DT_NEEDED entries naming the plain arguments
# (later entries move up, the freed slots become DT_NULL: what patchelf --remove-needed does),
# and renames each undefined, unversioned dynamic symbol OLD of an OLD=NEW argument to NEW by
# overwriting its string (NEW no longer than OLD, and no other name sharing those bytes).
import struct, sys
path, args = sys.argv[1], sys.argv[2:]
drop = {a for a in args if '=' not in a}
renames = dict(a.split('=', 1) for a in args if '=' in a)
data = bytearray(open(path, 'rb').read())
def fail(why):
    sys.exit(f'{path}: {why}')
if data[:4] != b'\x7fELF' or data[4] != 2 or data[5] != 1:
    fail('not a little-endian ELF64 file')
phoff, = struct.unpack_from('<Q', data, 0x20)
shoff, = struct.unpack_from('<Q', data, 0x28)
phentsize, phnum, shentsize, shnum = struct.unpack_from('<HHHH', data, 0x36)
phdrs = [struct.unpack_from('<IIQQQQQQ', data, phoff + i * phentsize) for i in range(phnum)]
# sh_name, sh_type, sh_flags, sh_addr, sh_offset, sh_size, sh_link, sh_info, sh_addralign, sh_entsize
sections = [struct.unpack_from('<IIQQQQIIQQ', data, shoff + i * shentsize) for i in range(shnum)]
loads = [p for p in phdrs if p[0] == 1]
dynamic = [p for p in phdrs if p[0] == 2]
if not dynamic:
    fail('no PT_DYNAMIC')
def file_offset(vaddr):
    for _, _, off, va, _, filesz, _, _ in loads:
        if va <= vaddr < va + filesz:
            return off + vaddr - va
    fail(f'address {vaddr:#x} is in no PT_LOAD')
d_off, d_size = dynamic[0][2], dynamic[0][5]
entries = [struct.unpack_from('<qQ', data, d_off + 16 * i) for i in range(d_size // 16)]
live = entries[:next(i for i, (tag, _) in enumerate(entries) if tag == 0)]
strtab = file_offset(next(v for tag, v in live if tag == 5))
def name(o):
    start = strtab + o
    return data[start:data.index(b'\0', start)].decode()

# Every reference into the dynamic string table: symbols, dynamic entries, version records.
refs = [v for t, v in live if t in (1, 14, 15, 29)]           # NEEDED, SONAME, RPATH, RUNPATH
dynsym = next((s for s in sections if s[1] == 11), None)      # SHT_DYNSYM
versym = next((s for s in sections if s[1] == 0x6fffffff), None)
if renames and dynsym is None:
    fail('no .dynsym section')
symbols = []
if dynsym is not None:
    for i in range(dynsym[5] // 24):
        st_name, _, _, st_shndx = struct.unpack_from('<IBBH', data, dynsym[4] + 24 * i)
        symbols.append((i, st_name, st_shndx))
        refs.append(st_name)
for s in sections:
    off, size = s[4], s[5]
    if s[1] == 0x6ffffffe:                                     # SHT_GNU_verneed
        p = off
        while True:
            _, cnt, vn_file, vn_aux, vn_next = struct.unpack_from('<HHIII', data, p)
            refs.append(vn_file)
            a = p + vn_aux
            for _ in range(cnt):
                _, _, _, vna_name, vna_next = struct.unpack_from('<IHHII', data, a)
                refs.append(vna_name)
                a += vna_next
            if not vn_next:
                break
            p += vn_next
    elif s[1] == 0x6ffffffd:                                   # SHT_GNU_verdef
        p = off
        while True:
            _, _, _, cnt, _, vd_aux, vd_next = struct.unpack_from('<HHHHIII', data, p)
            a = p + vd_aux
            for _ in range(cnt):
                vda_name, vda_next = struct.unpack_from('<II', data, a)
                refs.append(vda_name)
                a += vda_next
            if not vd_next:
                break
            p += vd_next

for old, new in renames.items():
    if len(new) > len(old):
        fail(f'{new} is longer than {old}')
    hits = [(i, o) for i, o, shndx in symbols if shndx == 0 and name(o) == old]
    if len(hits) != 1:
        fail(f'{len(hits)} undefined symbols named {old}')
    index, o = hits[0]
    if versym is not None and struct.unpack_from('<H', data, versym[4] + 2 * index)[0] > 1:
        fail(f'{old} is versioned')
    if sorted(r for r in refs if o <= r <= o + len(old)) != [o]:
        fail(f'another name shares the bytes of {old}')
    data[strtab + o:strtab + o + len(old)] = new.encode().ljust(len(old), b'\0')

kept = [(t, v) for t, v in live if not (t == 1 and name(v) in drop)]
if len(kept) != len(live) - len(drop):
    fail(f'not exactly one DT_NEEDED for each of {sorted(drop)}')
for i, (t, v) in enumerate(kept + [(0, 0)] * (len(entries) - len(kept))):
    struct.pack_into('<qQ', data, d_off + 16 * i, t, v)
open(path, 'r+b').write(data)
PY
        ! needed_of "$f" | grep -qx "$lib" || die "$(basename "$f") still needs $lib"
        echo "    $(basename "$f"): dropped DT_NEEDED $lib${renames[*]:+, renamed ${renames[*]}} (lazily bound: ${used//$'\n'/ })"
    done
    excluded[$lib]="Mesa's OSMesa (software fallback; needs libLLVM, 110 MiB): DT_NEEDED removed from the copies, OSMesaGetCurrentContext renamed glXGetCurrentContext"
done

# --- what run.sh needs to know -------------------------------------------------------------
# versions PATTERN DIR...: the newest symbol version matching PATTERN that the files there use
# (lib/cxx is left out of the C++ ones: libstdc++ lists every version it defines).
versions() { local p=$1; shift; find "$@" -type f -print0 | xargs -0 objdump -T 2>/dev/null | grep -o "${p}[0-9.]*" | sort -uV | tail -n 1; }
req_glibc=$(versions 'GLIBC_2\.' "$out/bin" "$out/lib" "$out/plugins")
req_glibcxx=$(versions 'GLIBCXX_3\.' "$out/bin" "$out/lib" "$out/plugins" -path "$out/lib/cxx" -prune -o)
req_cxxabi=$(versions 'CXXABI_1\.' "$out/bin" "$out/lib" "$out/plugins" -path "$out/lib/cxx" -prune -o)
{
    echo "# Written by scripts/gpu-bundle.sh; read by run.sh."
    echo "BUNDLE_TESTS='${tests[*]}'"
    echo "BUNDLE_FAKE_WORKER_PATH='$fake_worker_path'"
    echo "BUNDLE_REQ_GLIBC='${req_glibc#GLIBC_}'"
    echo "BUNDLE_REQ_GLIBCXX='$req_glibcxx'"
    echo "BUNDLE_REQ_CXXABI='$req_cxxabi'"
    echo "BUNDLE_SOURCE='$(git -C "$root" describe --always --dirty 2>/dev/null || echo unknown) $(date -u +%FT%TZ)'"
} > "$out/bundle.env"

# --- run.sh ---------------------------------------------------------------------------------
cat > "$out/run.sh" <<'RUN'
#!/usr/bin/env bash
# run.sh (written by scripts/gpu-bundle.sh): runs ShadowLab's GL tests, renders and benchmark from
# this bundle on a GPU machine with no display: Qt's headless platform (linked into the binaries)
# on EGL's device platform (EGL_EXT_platform_device, as on an NVIDIA GPU), the bundle's libraries
# first on LD_LIBRARY_PATH. Keeps going after a failure; writes, under ${OUT_DIR:-./results}:
#   summary.txt  PASS/FAIL/TIMEOUT/SKIP per step, the renderer, the machine (nvidia-smi -L)
#   env.txt      library path, GL/EGL libraries and vendor files found, ldd of bin/shadowlab
#   tst_*.log, tst_*.junit.xml       one per test (each under `timeout $TEST_TIMEOUT`)
#   render-<scene>.png, render-<scene>-depth.png, render-<scene>.log
#   bench-<scene>.json, bench-<scene>.log
# Order: tst_HeadlessPlatform (is there a GL 3.3 core context, and whose), renders, benches, then
# the other tests: the quick, telling steps first, should something stop the run.
#
#   ./run.sh                   all of it; exit status 0 when every step passed
#   ./run.sh exec CMD [ARG...] runs CMD in the same environment (bin/ first on PATH)
#
# Knobs (environment):
#   OUT_DIR=./results
#   SHADOWLAB_EGL_PLATFORM=device  a value set beforehand is kept: surfaceless takes Mesa's
#                      surfaceless platform (llvmpipe), empty tries surfaceless then device
#   SHADOWLAB_HEADLESS=egl  QT_QPA_PLATFORM=headless   (kept when set)
#   RUN_TESTS="tst_HeadlessPlatform tst_Shadows ..."  (default: every bundled test; "" none)
#   TEST_TIMEOUT=300   TEST_ARGS=""   (extra Qt Test arguments, e.g. a function name)
#   RENDER_SCENES="seed city"  RENDER_SIZE=1920x1080  RENDER_TIMEOUT=300   ("" skips)
#   BENCH_SCENES="seed city"   BENCH_SIZE=1920x1080   BENCH_TIMEOUT=300  BENCH_ARGS=""  ("" skips)
#   LINK_FAKE_WORKER=1  lets tst_ImportWorker run: symlinks the bundled fake-import-worker at the
#                      absolute path compiled into the test (otherwise it is skipped there)
#   BUNDLE_UNPACK_DIR  where payload.tar.xz is unpacked (default ${TMPDIR:-/tmp}/shadowlab-gpu-bundle-<id>)
set -uo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=/dev/null
. "$here/bundle.env"

# The payload: here, or packed in payload.tar.xz.
root=$here
if [ ! -d "$root/bin" ]; then
    payload=$here/payload.tar.xz
    [ -f "$payload" ] || { echo "run.sh: neither bin/ nor payload.tar.xz next to run.sh" >&2; exit 2; }
    root=${BUNDLE_UNPACK_DIR:-${TMPDIR:-/tmp}/shadowlab-gpu-bundle-$BUNDLE_PAYLOAD_ID}
    if [ ! -f "$root/.unpacked" ]; then
        echo "run.sh: unpacking payload.tar.xz into $root" >&2
        mkdir -p "$root" || exit 2
        if command -v xz >/dev/null; then
            tar -xJf "$payload" -C "$root" || exit 2
        elif command -v python3 >/dev/null; then
            python3 -c 'import sys, tarfile; tarfile.open(sys.argv[1]).extractall(sys.argv[2])' "$payload" "$root" || exit 2
        else
            echo "run.sh: need xz or python3 to unpack payload.tar.xz" >&2; exit 2
        fi
        touch "$root/.unpacked"
    fi
fi

ldconfig_p() { { ldconfig -p || /sbin/ldconfig -p; } 2>/dev/null; }
system_lib() { ldconfig_p | awk -v n="$1" '$1 == n && /x86-64/ {print $NF; exit}'; }
# in_path NAME: NAME in an LD_LIBRARY_PATH folder or the loader's cache
in_path() {
    local d IFS=:
    for d in ${LD_LIBRARY_PATH:-}; do [ -e "$d/$1" ] && { echo "$d/$1"; return; }; done
    system_lib "$1"
}

# --- environment ----------------------------------------------------------------------------
original_ld_path=${LD_LIBRARY_PATH:-}
ld_path=$root/lib
# libstdc++/libgcc_s: the machine's pair when its libstdc++ has what the bundle needs, else ours.
cxx_note="bundled (lib/cxx)"
sys_cxx=$(in_path libstdc++.so.6)
if [ -n "$sys_cxx" ] && grep -aqF "$BUNDLE_REQ_GLIBCXX" "$sys_cxx" && grep -aqF "$BUNDLE_REQ_CXXABI" "$sys_cxx"; then
    cxx_note="the machine's ($sys_cxx has $BUNDLE_REQ_GLIBCXX)"
else
    ld_path=$root/lib/cxx:$ld_path
fi
export LD_LIBRARY_PATH=$ld_path${original_ld_path:+:$original_ld_path}
# The GL/EGL dispatch libraries come from the driver; Debian's copies only where they are missing.
glvnd_note="the machine's"
if [ -d "$root/lib-glvnd-fallback" ]; then
    missing=""
    for n in libEGL.so.1 libGLX.so.0 libGLdispatch.so.0 libOpenGL.so.0; do [ -n "$(in_path "$n")" ] || missing+="$n "; done
    if [ -n "$missing" ]; then
        glvnd_note="FALLBACK: bundled Debian glvnd, the machine lacks $missing"
        export LD_LIBRARY_PATH=$LD_LIBRARY_PATH:$root/lib-glvnd-fallback
    fi
fi
unset LD_BIND_NOW                                      # the dropped OSMesa calls must stay lazy
export QT_PLUGIN_PATH=$root/plugins
export QT_QPA_PLATFORM=${QT_QPA_PLATFORM:-headless}
export SHADOWLAB_HEADLESS=${SHADOWLAB_HEADLESS:-egl}   # never the OSMesa fallback: not in the bundle
export SHADOWLAB_EGL_PLATFORM=${SHADOWLAB_EGL_PLATFORM-device}
export SHADOWLAB_IMPORT_WORKER=${SHADOWLAB_IMPORT_WORKER:-$root/bin/shadowlab-import-worker}
export PATH=$root/bin:$PATH
# The NVIDIA EGL vendor file: glvnd finds no vendor without one (containers started without the
# "graphics" driver capability lack it); write one where libEGL_nvidia is there but its file is not.
vendor_note="glvnd's vendor folders"
if [ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}${__EGL_VENDOR_LIBRARY_DIRS:-}" ] && \
   ! grep -qsl nvidia /etc/glvnd/egl_vendor.d/*.json /usr/share/glvnd/egl_vendor.d/*.json /usr/local/share/glvnd/egl_vendor.d/*.json; then
    nvidia_egl=$(in_path libEGL_nvidia.so.0)
    if [ -n "$nvidia_egl" ]; then
        vendor_dir=${TMPDIR:-/tmp}/shadowlab-egl-vendor-$(id -u)
        mkdir -p "$vendor_dir"
        printf '{\n    "file_format_version" : "1.0.0",\n    "ICD" : { "library_path" : "%s" }\n}\n' "$nvidia_egl" > "$vendor_dir/10_nvidia.json"
        export __EGL_VENDOR_LIBRARY_FILENAMES=$vendor_dir/10_nvidia.json
        vendor_note="WRITTEN: $vendor_dir/10_nvidia.json (no nvidia vendor file found)"
    else
        vendor_note="no nvidia vendor file and no libEGL_nvidia.so.0"
    fi
fi
if [ -z "${FONTCONFIG_FILE:-}" ] && [ -f "$root/fonts/DejaVuSans.ttf" ]; then
    fc_dir=${TMPDIR:-/tmp}/shadowlab-fontconfig-$(id -u)
    mkdir -p "$fc_dir"
    # Only the bundled font, rasterised with Debian's defaults (grey antialiasing, slight
    # hinting), so the depth view's legend comes out as it does from a Debian build.
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
fi

if [ "${1:-}" = exec ]; then
    shift
    [ $# -gt 0 ] || { echo "usage: run.sh exec CMD [ARG...]" >&2; exit 2; }
    exec "$@"
fi

# --- the run --------------------------------------------------------------------------------
results=${OUT_DIR:-./results}
mkdir -p "$results" && results=$(cd "$results" && pwd) || exit 2
work=$results/work                                      # the programs' current folder
mkdir -p "$work"
summary=$results/summary.txt
failures=0
say() { echo "$*" | tee -a "$summary"; }
# record NAME RC SECONDS [DETAIL]
record() {
    local status=FAIL
    case "$2" in 0) status=PASS ;; 124|137) status=TIMEOUT ;; skip) status=SKIP ;; esac
    [ "$status" = PASS ] || [ "$status" = SKIP ] || failures=$((failures + 1))
    say "$(printf '%-8s %-28s %5ss  %s' "$status" "$1" "$3" "${4:-}")"
}

: > "$summary"
say "ShadowLab GPU bundle ($BUNDLE_SOURCE) on $(uname -n), $(date -u +%FT%TZ)"
if command -v nvidia-smi >/dev/null; then
    nvidia-smi -L 2>&1 | sed 's/^/  /' | tee -a "$summary"
else
    say "  (no nvidia-smi)"
fi
glibc=$(getconf GNU_LIBC_VERSION 2>/dev/null | awk '{print $2}')
say "  glibc ${glibc:-?} (bundle needs >= $BUNDLE_REQ_GLIBC); libstdc++: $cxx_note; glvnd: $glvnd_note"
say "  EGL vendors: $vendor_note; QT_QPA_PLATFORM=$QT_QPA_PLATFORM SHADOWLAB_HEADLESS=$SHADOWLAB_HEADLESS SHADOWLAB_EGL_PLATFORM=${SHADOWLAB_EGL_PLATFORM:-<empty: surfaceless, then device>}"
{
    echo "LD_LIBRARY_PATH=$LD_LIBRARY_PATH"
    echo "QT_PLUGIN_PATH=$QT_PLUGIN_PATH FONTCONFIG_FILE=${FONTCONFIG_FILE:-} __EGL_VENDOR_LIBRARY_FILENAMES=${__EGL_VENDOR_LIBRARY_FILENAMES:-}"
    echo "--- GL/EGL/NVIDIA libraries in the loader cache"
    ldconfig_p | grep -E 'lib(EGL|GLX|GL|OpenGL|GLdispatch|gbm|nvidia-egl|nvidia-glcore|EGL_nvidia|GLX_nvidia)[._]' || echo "(none)"
    echo "--- EGL vendor files"
    ls -l /etc/glvnd/egl_vendor.d /usr/share/glvnd/egl_vendor.d /usr/local/share/glvnd/egl_vendor.d 2>&1
    cat /proc/driver/nvidia/version 2>/dev/null
    echo "--- ldd bin/shadowlab"
    ldd "$root/bin/shadowlab" 2>&1
} > "$results/env.txt"
if grep -q 'not found' "$results/env.txt"; then
    say "  WARNING: unresolved libraries: $(grep 'not found' "$results/env.txt" | awk '{print $1}' | tr '\n' ' ')"
fi

run_test() {
    local t=$1 start rc detail
    if [ ! -x "$root/bin/$t" ]; then record "$t" skip 0 "not in this bundle"; return; fi
    if [ "$t" = tst_ImportWorker ] && [ -n "$BUNDLE_FAKE_WORKER_PATH" ] && [ ! -x "$BUNDLE_FAKE_WORKER_PATH" ]; then
        if [ "${LINK_FAKE_WORKER:-0}" = 1 ] && mkdir -p "$(dirname "$BUNDLE_FAKE_WORKER_PATH")" &&
           ln -sf "$root/bin/fake-import-worker" "$BUNDLE_FAKE_WORKER_PATH"; then
            :
        else
            record "$t" skip 0 "calls $BUNDLE_FAKE_WORKER_PATH (compiled in); LINK_FAKE_WORKER=1 links it"
            return
        fi
    fi
    start=$(date +%s)
    # shellcheck disable=SC2086
    (cd "$work" && timeout -k 10 "${TEST_TIMEOUT:-300}" "$root/bin/$t" -o "$results/$t.junit.xml,junitxml" -o -,txt ${TEST_ARGS:-}) \
        > "$results/$t.log" 2>&1
    rc=$?
    detail=$(grep -m1 '^Totals:' "$results/$t.log" || tail -n 1 "$results/$t.log")
    record "$t" "$rc" "$(( $(date +%s) - start ))" "$detail"
    if [ "$t" = tst_HeadlessPlatform ]; then
        grep -m1 -o 'GL_RENDERER: .*' "$results/$t.log" | sed 's/^/  /' | tee -a "$summary"
    fi
}

tests=${RUN_TESTS-$BUNDLE_TESTS}
case " $tests " in *" tst_HeadlessPlatform "*) run_test tst_HeadlessPlatform ;; esac

for scene in ${RENDER_SCENES-seed city}; do
    start=$(date +%s)
    (cd "$work" && timeout -k 10 "${RENDER_TIMEOUT:-300}" "$root/bin/shadowlab" render --scene "$scene" --size "${RENDER_SIZE:-1920x1080}" \
        --out "$results/render-$scene.png" --depth-out "$results/render-$scene-depth.png") > "$results/render-$scene.log" 2>&1
    rc=$?
    [ "$rc" != 0 ] || [ -s "$results/render-$scene.png" ] || rc=1
    record "render $scene" "$rc" "$(( $(date +%s) - start ))" "render-$scene.png"
done

for scene in ${BENCH_SCENES-seed city}; do
    start=$(date +%s)
    # shellcheck disable=SC2086
    (cd "$work" && timeout -k 10 "${BENCH_TIMEOUT:-300}" "$root/bin/shadowlab" bench --json --scene "$scene" --size "${BENCH_SIZE:-1920x1080}" ${BENCH_ARGS:-}) \
        > "$results/bench-$scene.json" 2> "$results/bench-$scene.log"
    rc=$?
    [ "$rc" != 0 ] || head -c 1 "$results/bench-$scene.json" | grep -q '{' || rc=1
    renderer=$(sed -n 's/^ *"renderer": "\(.*\)",*$/\1/p' "$results/bench-$scene.json" | head -n 1)
    record "bench $scene" "$rc" "$(( $(date +%s) - start ))" "${renderer:+renderer: $renderer}"
done

for t in $tests; do
    [ "$t" = tst_HeadlessPlatform ] || run_test "$t"
done

say "overall: $failures step(s) failed; results in $results"
[ "$failures" = 0 ]
RUN
chmod +x "$out/run.sh"

# --- manifest, size, packing ----------------------------------------------------------------
{
    echo "ShadowLab GPU bundle from $build_dir ($(git -C "$root" describe --always --dirty 2>/dev/null || echo unknown))"
    echo "needs: glibc >= ${req_glibc#GLIBC_}, $req_glibcxx, $req_cxxabi; the NVIDIA driver's libEGL/libGLX/libOpenGL/libGLdispatch and EGL vendor library"
    echo
    echo "== bundled (size, name, from)"
    for name in $(printf '%s\n' "${!bundled[@]}" | sort); do
        printf '%10s  %-28s %s\n' "$(stat -c %s "$out/${bundled[$name]}/$name")" "${bundled[$name]}/$name" "${where[$name]}"
    done
    echo
    echo "== left out (name: why)"
    for name in $(printf '%s\n' "${!excluded[@]}" | sort); do echo "$name: ${excluded[$name]}"; done
    for name in $(printf '%s\n' "${!only_via[@]}" | sort); do echo "$name: ${only_via[$name]}"; done
} > "$out/MANIFEST.txt"

payload_dirs=(bin lib plugins fonts)
[ -d "$out/lib-glvnd-fallback" ] && payload_dirs+=(lib-glvnd-fallback)
size_kib=$(du -sk "$out" | cut -f1)
note "unpacked: $(du -sh "$out" | cut -f1) (limit ${limit_mib} MiB)"
if [ "$pack" = always ] || { [ "$pack" = auto ] && [ "$size_kib" -gt $((limit_mib * 1024)) ]; }; then
    note "packing ${payload_dirs[*]} into payload.tar.xz (xz -6, two threads: a minute or two)"
    tar -C "$out" -cf - "${payload_dirs[@]}" | xz -6 -T2 > "$out/payload.tar.xz"
    (cd "$out" && rm -rf "${payload_dirs[@]}")
    echo "BUNDLE_PAYLOAD_ID='$(cksum < "$out/payload.tar.xz" | cut -d' ' -f1)'" >> "$out/bundle.env"
else
    echo "BUNDLE_PAYLOAD_ID=''" >> "$out/bundle.env"
fi
size_kib=$(du -sk "$out" | cut -f1)
note "bundle: $out, $(du -sh "$out" | cut -f1)"
[ "$size_kib" -le $((limit_mib * 1024)) ] || echo "warning: over ${limit_mib} MiB; see MANIFEST.txt for the largest libraries" >&2
