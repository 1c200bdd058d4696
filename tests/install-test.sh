#!/usr/bin/env bash
# ShadowLab as a user gets it. `cmake --install` into a temporary prefix; the desktop entry and
# metainfo through their validators; the icon sizes, man page and completion in place; then the
# installed program, with nothing of the build tree in its environment, renders a scene preset
# and a model file (read by the installed import worker) headless. Then the same for the Debian
# package CPack makes, unpacked with dpkg-deb. Usage: install-test.sh BUILD_DIR
set -euo pipefail
build=$(cd "$1" && pwd -P)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
case "$(cd "$work" && pwd -P)/" in
    "$build"/*) echo "FAIL: the temporary folder $work is inside the build tree; set TMPDIR elsewhere" >&2; exit 1 ;;
esac
app_id=org.shadowlab.ShadowLab

fail() {
    echo "FAIL: $*" >&2
    exit 1
}

# The program with a bare environment: no SHADOWLAB_*, QT_*, DISPLAY or build paths.
run_clean() {
    (cd "$work" && env -i PATH=/usr/bin:/bin HOME="$work/home" LANG=C.UTF-8 "$@")
}

# "WIDTHxHEIGHT" of a PNG file, from its header.
png_size() {
    python3 -c 'import struct, sys
data = open(sys.argv[1], "rb").read(24)
assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
print("%dx%d" % struct.unpack(">II", data[16:24]))' "$1"
}

check_tree() {
    local prefix=$1
    local f
    for f in bin/shadowlab libexec/shadowlab/shadowlab-import-worker; do
        [ -x "$prefix/$f" ] || fail "$prefix/$f is missing or not executable"
    done
    for f in share/applications/$app_id.desktop share/metainfo/$app_id.metainfo.xml share/man/man1/shadowlab.1 \
             share/bash-completion/completions/shadowlab share/icons/hicolor/scalable/apps/$app_id.svg; do
        [ -s "$prefix/$f" ] || fail "$prefix/$f is missing or empty"
    done
    local size
    for size in 16 22 24 32 48 64 128 256 512; do
        f=$prefix/share/icons/hicolor/${size}x${size}/apps/$app_id.png
        [ -f "$f" ] || fail "$f is missing"
        [ "$(png_size "$f")" = "${size}x${size}" ] || fail "$f is $(png_size "$f"), not ${size}x${size}"
    done
    echo "== desktop-file-validate"
    desktop-file-validate "$prefix/share/applications/$app_id.desktop" || fail "desktop-file-validate"
    echo "== appstreamcli validate --no-net"
    appstreamcli validate --no-net "$prefix/share/metainfo/$app_id.metainfo.xml" || fail "appstreamcli validate"
    # The licence, said the same everywhere: LICENSE, the Debian copyright file, the metainfo.
    cmp -s "$prefix/share/doc/shadowlab/LICENSE" "$(dirname "${BASH_SOURCE[0]}")/../LICENSE" || fail "share/doc/shadowlab/LICENSE is not the repository's LICENSE"
    grep -q '^License: Expat$' "$prefix/share/doc/shadowlab/copyright" || fail "the copyright file names no Expat (MIT) licence"
    grep -q '^Copyright: .*ShadowLab developers' "$prefix/share/doc/shadowlab/copyright" || fail "the copyright file names no holder"
    grep -q '<project_license>MIT</project_license>' "$prefix/share/metainfo/$app_id.metainfo.xml" || fail "the metainfo names no MIT licence"
    grep -q '^\.TH SHADOWLAB 1' "$prefix/share/man/man1/shadowlab.1" || fail "shadowlab.1 has no .TH line"
    local version
    version=$("$prefix/bin/shadowlab" --version | head -n 1 | cut -d ' ' -f 2)
    grep '^\.TH SHADOWLAB 1' "$prefix/share/man/man1/shadowlab.1" | grep -qF "ShadowLab $version" || fail "shadowlab.1's .TH line does not name version $version"
    for command in render bench report settings audit tune screenshot; do
        grep -q "^\.SS \"shadowlab $command" "$prefix/share/man/man1/shadowlab.1" || fail "shadowlab.1 has no section on $command"
    done
    # No run path into the build tree (Qt's own, relative to $ORIGIN, may stay).
    if readelf -d "$prefix/bin/shadowlab" "$prefix/libexec/shadowlab/shadowlab-import-worker" | grep -E 'R(UN)?PATH' | grep -E '(\[|:)/'; then
        fail "an installed binary keeps an absolute run path"
    fi
}

# What bash would offer after `line` (the cursor at its end), from the installed completion.
complete_line() {
    local completion=$1 line=$2
    # In a folder of its own: where nothing else matches, bash falls back to the file names here.
    (cd "$work/home" && bash -c '
        compopt() { :; }
        source "$1"
        COMP_LINE=$2 COMP_POINT=${#2}
        read -ra COMP_WORDS <<<"${2//=/ = }"
        [[ $2 == *" " ]] && COMP_WORDS+=("")
        COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
        _shadowlab
        printf "%s\n" "${COMPREPLY[@]}" | sort | tr "\n" " "' _ "$completion" "$line")
}

check_completion() {
    local completion=$1/share/bash-completion/completions/shadowlab
    expect() {
        local got
        got=$(complete_line "$completion" "$1")
        [ "$got" = "$2" ] || fail "completing '$1' gave '$got', not '$2'"
    }
    expect "shadowlab ren" "render "
    expect "shadowlab help sc" "screenshot "
    expect "shadowlab render --de" "--depth-out "
    expect "shadowlab render --preset ac" "acne "
    expect "shadowlab bench --scene ci" "city "
    expect "shadowlab render --set bias.sl" "bias.slope= "
    expect "shadowlab render --set filter.mode=pcf" "pcf pcf-dither4 pcf-optimized pcf64 "
    expect "shadowlab --set shadow.enabled=" "=false =true "
}

check_program() {
    local prefix=$1 name=$2
    local program=$prefix/bin/shadowlab
    run_clean "$program" --version | grep -q '^shadowlab ' || fail "$program --version"
    run_clean "$program" --version | grep -q '^Licence: MIT' || fail "$program --version names no licence"
    run_clean "$program" help render | grep -q -- '--size' || fail "$program help render"
    echo "== $name: render --scene seed"
    run_clean "$program" render --scene seed --size 160x90 --out "$work/$name-seed.png" || fail "$program render --scene seed"
    [ "$(png_size "$work/$name-seed.png")" = 160x90 ] || fail "$name-seed.png is not a 160x90 PNG"
    # A model file is read by the worker in libexec/shadowlab, the installed one: a program
    # outside the build tree never falls back to the worker the build made.
    echo "== $name: render --scene box.obj (through the import worker)"
    run_clean "$program" render --scene "$work/box.obj" --size 160x90 --out "$work/$name-box.png" || fail "$program render --scene box.obj"
    [ "$(png_size "$work/$name-box.png")" = 160x90 ] || fail "$name-box.png is not a 160x90 PNG"
}

cat >"$work/box.obj" <<'EOF'
v -1 0 -1
v 1 0 -1
v 1 0 1
v -1 0 1
v -0.3 0.6 -0.3
v 0.3 0.6 -0.3
v 0.3 0.6 0.3
v -0.3 0.6 0.3
f 1 3 2
f 1 4 3
f 5 6 7
f 5 7 8
EOF
mkdir -p "$work/home"

echo "== cmake --install $build --prefix $work/prefix"
cmake --install "$build" --prefix "$work/prefix" >"$work/install.log" || { cat "$work/install.log"; fail "cmake --install"; }
check_tree "$work/prefix"
check_completion "$work/prefix"
check_program "$work/prefix" installed

# Without the installed worker the import must fail, naming the worker: proof that the program
# above used the installed one and not the build tree's.
cp -a "$work/prefix" "$work/no-worker"
rm "$work/no-worker/libexec/shadowlab/shadowlab-import-worker"
if run_clean "$work/no-worker/bin/shadowlab" render --scene "$work/box.obj" --size 16x16 --out "$work/none.png" 2>"$work/no-worker.log"; then
    fail "an installed program without its worker still read a model file"
fi
grep -q 'import worker' "$work/no-worker.log" || { cat "$work/no-worker.log"; fail "the refusal does not name the import worker"; }

echo "== cpack (DEB)"
cpack --config "$build/CPackConfig.cmake" -B "$work/package" >"$work/cpack.log" || { cat "$work/cpack.log"; fail "cpack"; }
deb=$(ls "$work"/package/*.deb)
depends=$(dpkg-deb --field "$deb" Depends)
echo "Depends: $depends"
# Library packages by their stems (their names carry ABI versions that change between releases).
for package in libqt6gui6 libqt6widgets6 libqt6charts6 libassimp libembree libgl1-mesa-dri qt6-qpa-plugins qt6-image-formats-plugins; do
    [[ $depends == *"$package"* ]] || fail "the package does not depend on $package"
done
dpkg-deb -x "$deb" "$work/deb"
check_tree "$work/deb/usr"
check_program "$work/deb/usr" deb
echo "PASS"
