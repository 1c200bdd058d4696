#!/usr/bin/env python3
"""Write reproducibly damaged copies of real model files, for surveying the model loader.

Usage: damage-models.py OUTDIR [--count N] [--seed S] [--models DIR] [--pristine]

Sources are the good files of Debian's assimp-testmodels (/usr/share/assimp/models) in the
formats glb, gltf, obj, ply, stl, dae, fbx, 3ds and off (paths naming a deliberately broken
case, such as "invalid", and files that even undamaged have no triangles or cannot be read are
skipped; files under 2 MB are preferred). Each output file gets
one kind of damage, cycling evenly through formats and kinds:

  flip       flip a few random bytes
  truncate   cut the file at a random point (half the time inside the first 5-200 bytes)
  inflate    multiply a count in a text header by 10^3..10^9 (PLY 'element', OFF counts,
             glTF/COLLADA/FBX counts, OBJ face indices), or overwrite a little-endian uint32
             near the start of a binary file (glb/3ds/fbx/stl) with a huge value
  duplicate  copy a run of bytes and insert it again
  numbers    replace some numeric tokens with 1e38, -nan, inf, 99999999999, 0, 1.2.3, ...
             (in binary data: 32-bit words with NaN, inf, 1e38, 0xffffffff, ...)

glb JSON edits rebuild the chunk framing, so the damage is in the content. Output goes to
OUTDIR/<format>/<index>-<kind>-<basename>; a .gltf's external buffers and images and an
.obj's material libraries are copied next to it unchanged (into OUTDIR/<format>/<index>/
instead when a companion of the same name but other content is already there). The result
depends only on the seed, the count and the models folder. --pristine writes each chosen
source once, undamaged (kind "none"), for a baseline.
"""

import argparse
import collections
import json
import os
import random
import re
import shutil
import struct
import sys
import urllib.parse

FORMATS = ["glb", "gltf", "obj", "ply", "stl", "dae", "fbx", "3ds", "off"]
KINDS = ["flip", "truncate", "inflate", "duplicate", "numbers"]

# Paths in assimp-testmodels that are broken on purpose, or that even undamaged carry no
# triangles or cannot be read (refused by ShadowLab as shipped): regexes on "/" + relative path.
BROKEN = [r"invalid", r"schemafailures", r"wrongtypes", r"indexoutofrange", r"incorrectvertexarrays",
          r"missingbin", r"recursivenodes", r"boxwithinfinites", r"boxbadnormals", r"issue_3269",
          r"draco", r"testnorootnode", r"utf16", r"/gltf/boxtextured-gltf-binary/",
          r"mesh_primitivemode_(0[0-3]|0[7-9]|10)\.", r"/collada/(cameras|lights|library_animation_clips)\.",
          r"transparenttest\.", r"/obj/(point_cloud|testline|testpoints)\.", r"/ply/(issue623|points)\.",
          r"triangle_with_empty_solid"]
SIZE_PREFERRED = 2 * 1024 * 1024

NUMBER_RE = re.compile(rb"(?<![A-Za-z0-9_.#-])-?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?(?![A-Za-z0-9_.])")
REPLACEMENTS = [b"1e38", b"-nan", b"inf", b"99999999999", b"0", b"1.2.3", b"-1", b"nan",
                b"-1e38", b"1e-45", b"-0", b"4294967296", b"-inf"]
BINARY_WORDS = [struct.pack("<f", float("nan")), struct.pack("<f", float("inf")),
                struct.pack("<f", float("-inf")), struct.pack("<f", 1e38), struct.pack("<f", -1e38),
                b"\xff\xff\xff\xff", b"\x00\x00\x00\x80", b"\x00\x00\x00\x00", b"\xff\xff\xff\x7f",
                b"\x01\x00\x00\x00"]
HUGE_U32 = [0xFFFFFFFF, 0xFFFFFFFE, 0x7FFFFFFF, 0x80000000, 0x40000000, 0x10000000, 0x0FFFFFFF]


def find_sources(models):
    by_format = {f: [] for f in FORMATS}
    for root, dirs, files in os.walk(models):
        dirs.sort()
        for name in sorted(files):
            path = os.path.join(root, name)
            ext = os.path.splitext(name)[1][1:].lower()
            rel = os.path.relpath(path, models).lower()
            if ext in by_format and not any(re.search(b, "/" + rel) for b in BROKEN) and os.path.isfile(path):
                by_format[ext].append(path)
    for fmt, paths in by_format.items():
        small = [p for p in paths if os.path.getsize(p) < SIZE_PREFERRED]
        by_format[fmt] = small or paths
    return by_format


# ---------------------------------------------------------------- format helpers

def is_binary_stl(data):
    if len(data) >= 84:
        n = struct.unpack_from("<I", data, 80)[0]
        if 84 + 50 * n == len(data):
            return True
    return not data.lstrip()[:5].lower() == b"solid"


def is_binary_fbx(data):
    return data.startswith(b"Kaydara FBX Binary")


def ply_body_offset(data):
    i = data.find(b"end_header")
    if i < 0:
        return None
    j = data.find(b"\n", i)
    return j + 1 if j >= 0 else len(data)


def ply_is_binary(data):
    return re.search(rb"^format\s+binary", data[:4096], re.M) is not None


def split_glb(data):
    """Return (json_bytes, rest_chunks) or None when the framing is not readable."""
    if len(data) < 20 or data[:4] != b"glTF":
        return None
    jlen, jtype = struct.unpack_from("<II", data, 12)
    if jtype != 0x4E4F534A or 20 + jlen > len(data):
        return None
    return data[20:20 + jlen], data[20 + jlen:]


def join_glb(version, js, rest):
    js = js + b" " * (-len(js) % 4)
    body = struct.pack("<II", len(js), 0x4E4F534A) + js + rest
    return b"glTF" + struct.pack("<II", version, 12 + len(body)) + body


def text_region(fmt, data):
    """(start, end) of the part of the file where numeric tokens are text, or None."""
    if fmt in ("obj", "off", "gltf", "dae"):
        return 0, len(data)
    if fmt == "ply":
        body = ply_body_offset(data)
        if ply_is_binary(data):
            return None
        return (body or 0), len(data)
    if fmt == "stl":
        return None if is_binary_stl(data) else (0, len(data))
    if fmt == "fbx":
        return None if is_binary_fbx(data) else (0, len(data))
    return None  # glb (handled through its JSON), 3ds


def binary_region(fmt, data):
    """(start, end) of binary payload for word replacement."""
    if fmt == "ply":
        return ply_body_offset(data) or 0, len(data)
    if fmt == "stl":
        return min(84, len(data)), len(data)
    if fmt == "fbx":
        return min(27, len(data)), len(data)
    if fmt == "glb":
        return min(20, len(data)), len(data)
    return min(6, len(data)), len(data)


def chunk_length_offsets_3ds(data):
    """Offsets of uint32 chunk lengths in a 3DS file: the main chunk, its children, and theirs."""
    offsets = []

    def walk(start, end, depth):
        pos = start
        while pos + 6 <= end and len(offsets) < 64:
            cid, clen = struct.unpack_from("<HI", data, pos)
            offsets.append(pos + 2)
            if clen < 6:
                break
            if depth < 3 and cid in (0x4D4D, 0x3D3D, 0x4100, 0xB000, 0xAFFF):
                walk(pos + 6, min(pos + clen, end), depth + 1)
            elif depth < 3 and cid == 0x4000:
                z = data.find(b"\0", pos + 6, min(pos + clen, end))
                if z >= 0:
                    walk(z + 1, min(pos + clen, end), depth + 1)
            pos += clen
    walk(0, len(data), 0)
    # vertex/face list counts (uint16) inside mesh chunks
    for cid in (b"\x10\x41", b"\x20\x41", b"\x40\x41"):
        i = data.find(cid)
        if i >= 0 and i + 8 <= len(data):
            offsets.append(("u16", i + 6))
    return offsets


# ---------------------------------------------------------------- damage kinds

def damage_flip(rng, fmt, data):
    data = bytearray(data)
    n = rng.randint(1, 8)
    where = []
    for _ in range(n):
        i = rng.randrange(len(data))
        data[i] ^= rng.randint(1, 255)
        where.append(i)
    return bytes(data), "flipped %d bytes at %s" % (n, ",".join(map(str, sorted(where))))


def damage_truncate(rng, fmt, data):
    if rng.random() < 0.5 or len(data) <= 200:
        cut = rng.randint(5, min(200, max(5, len(data) - 1)))
    else:
        cut = rng.randint(201, len(data) - 1)
    return data[:cut], "truncated to %d of %d bytes" % (cut, len(data))


def inflate_text(rng, data, patterns, start=0, end=None):
    end = len(data) if end is None else end
    hits = []
    for pat in patterns:
        hits += [m for m in re.finditer(pat, data[start:end], re.M)]
        if hits:
            break
    if not hits:
        return None
    m = rng.choice(hits)
    a, b = start + m.start(1), start + m.end(1)
    old = int(data[a:b])
    new = max(old, 1) * 10 ** rng.randint(3, 9)
    return data[:a] + str(new).encode() + data[b:], "count %d -> %d at byte %d" % (old, new, a)


def overwrite_u32(rng, data, offsets):
    off = rng.choice(offsets)
    data = bytearray(data)
    if isinstance(off, tuple):
        _, o = off
        data[o:o + 2] = b"\xff\xff"
        return bytes(data), "uint16 at %d -> 65535" % o
    value = rng.choice(HUGE_U32)
    data[off:off + 4] = struct.pack("<I", value)
    return bytes(data), "uint32 at %d -> %#x" % (off, value)


def damage_inflate(rng, fmt, data):
    if fmt == "ply":
        r = inflate_text(rng, data, [rb"^element\s+\S+\s+(\d+)"], 0, ply_body_offset(data))
        if r:
            return r
    elif fmt == "off":
        lines = re.finditer(rb"^[ \t]*(\d+)[ \t]+(\d+)[ \t]+(\d+)", data[:2048], re.M)
        m = next(lines, None)
        if m:
            g = rng.randint(1, 2)  # vertex or face count
            a, b = m.start(g), m.end(g)
            old = int(data[a:b])
            new = max(old, 1) * 10 ** rng.randint(3, 9)
            return data[:a] + str(new).encode() + data[b:], "count %d -> %d at byte %d" % (old, new, a)
    elif fmt == "obj":
        r = inflate_text(rng, data, [rb"^f[ \t]+(\d+)", rb"^f[ \t]+\S+[ \t]+(\d+)", rb"^[lp][ \t]+(\d+)"])
        if r:
            return r[0], "face index " + r[1][len("count "):]
    elif fmt == "gltf":
        r = inflate_text(rng, data, [rb'"count"\s*:\s*(\d+)', rb'"byteLength"\s*:\s*(\d+)'])
        if r:
            return r
    elif fmt == "dae":
        r = inflate_text(rng, data, [rb'\bcount="(\d+)"'])
        if r:
            return r
    elif fmt == "fbx" and not is_binary_fbx(data):
        r = inflate_text(rng, data, [rb"\*(\d+)\s*\{"])
        if r:
            return r
    elif fmt == "stl" and not is_binary_stl(data):
        pass  # ASCII STL has no counts; fall through to the uint32 overwrite
    elif fmt == "glb" and rng.random() < 0.5:
        parts = split_glb(data)
        if parts:
            js, rest = parts
            r = inflate_text(rng, js, [rb'"count"\s*:\s*(\d+)'])
            if r:
                return join_glb(struct.unpack_from("<I", data, 4)[0], r[0], rest), "JSON " + r[1]
    # binary: a uint32 near the start
    if fmt == "glb":
        offsets = [8, 12]
        parts = split_glb(data)
        if parts and len(parts[1]) >= 8:
            offsets.append(20 + struct.unpack_from("<I", data, 12)[0])
    elif fmt == "3ds":
        offsets = chunk_length_offsets_3ds(data)
    elif fmt == "fbx" and is_binary_fbx(data):
        offsets = [23, 27, 31, 35, 39, 43]
    elif fmt == "stl":
        offsets = [80]
    else:
        offsets = [0]
    offsets = [o for o in offsets if (o[1] + 2 if isinstance(o, tuple) else o + 4) <= len(data)]
    if not offsets:
        return damage_flip(rng, fmt, data)
    return overwrite_u32(rng, data, offsets)


def damage_duplicate(rng, fmt, data):
    n = rng.randint(1, max(1, min(4096, len(data) // 2)))
    src = rng.randrange(0, len(data) - n + 1)
    dst = src + n if rng.random() < 0.5 else rng.randrange(0, len(data) + 1)
    chunk = data[src:src + n]
    return data[:dst] + chunk + data[dst:], "duplicated %d bytes from %d at %d" % (n, src, dst)


def replace_numbers(rng, data, start, end):
    hits = list(NUMBER_RE.finditer(data, start, end))
    if not hits:
        return None
    picks = sorted(rng.sample(hits, min(len(hits), rng.randint(1, 10))), key=lambda m: m.start())
    out, last, notes = [], 0, []
    for m in picks:
        rep = rng.choice(REPLACEMENTS)
        out += [data[last:m.start()], rep]
        last = m.end()
        notes.append("%d:%s" % (m.start(), rep.decode()))
    out.append(data[last:])
    return b"".join(out), "numbers " + " ".join(notes)


def damage_numbers(rng, fmt, data):
    if fmt == "glb":
        parts = split_glb(data)
        if parts:
            js, rest = parts
            r = replace_numbers(rng, js, 0, len(js))
            if r:
                return join_glb(struct.unpack_from("<I", data, 4)[0], r[0], rest), "JSON " + r[1]
    region = text_region(fmt, data)
    if region:
        r = replace_numbers(rng, data, *region)
        if r:
            return r
    start, end = binary_region(fmt, data)
    data = bytearray(data)
    n = rng.randint(1, 10)
    notes = []
    for _ in range(n):
        if end - start < 4:
            break
        o = start + (rng.randrange(0, end - start - 3) & ~3)
        w = rng.choice(BINARY_WORDS)
        data[o:o + 4] = w
        notes.append("%d:%s" % (o, w.hex()))
    return bytes(data), "words " + " ".join(notes)


DAMAGE = {"flip": damage_flip, "truncate": damage_truncate, "inflate": damage_inflate,
          "duplicate": damage_duplicate, "numbers": damage_numbers}


# ---------------------------------------------------------------- companions

def companions(fmt, path, data):
    """Relative paths of the files the model references that exist next to it."""
    rels = []
    if fmt == "gltf":
        try:
            doc = json.loads(data.decode("utf-8-sig"))
        except (ValueError, UnicodeDecodeError):
            doc = {}
        for key in ("buffers", "images", "shaders"):
            items = doc.get(key, [])
            items = items.values() if isinstance(items, dict) else items  # glTF 1 uses objects
            for item in items:
                uri = item.get("uri") if isinstance(item, dict) else None
                if isinstance(uri, str) and not uri.startswith("data:"):
                    rels.append(urllib.parse.unquote(uri))
    elif fmt == "obj":
        for m in re.finditer(rb"^mtllib[ \t]+(.+?)[ \t]*\r?$", data, re.M):
            rels.append(m.group(1).decode("utf-8", "replace"))
    base = os.path.dirname(path)
    out = []
    for rel in rels:
        rel = os.path.normpath(rel)
        if rel.startswith("..") or os.path.isabs(rel):
            continue
        if os.path.isfile(os.path.join(base, rel)) and rel not in out:
            out.append(rel)
    return out


def same_file(a, b):
    with open(a, "rb") as fa, open(b, "rb") as fb:
        return fa.read() == fb.read()


def write_output(outdir, fmt, index, kind, src, damaged):
    fmtdir = os.path.join(outdir, fmt)
    with open(src, "rb") as f:
        original = f.read()
    comps = companions(fmt, src, original)
    dest_dir = fmtdir
    for rel in comps:
        d = os.path.join(fmtdir, rel)
        if os.path.exists(d) and not same_file(d, os.path.join(os.path.dirname(src), rel)):
            dest_dir = os.path.join(fmtdir, "%03d" % index)
            break
    for rel in comps:
        d = os.path.join(dest_dir, rel)
        if not os.path.exists(d):
            os.makedirs(os.path.dirname(d), exist_ok=True)
            shutil.copyfile(os.path.join(os.path.dirname(src), rel), d)
    os.makedirs(dest_dir, exist_ok=True)
    out = os.path.join(dest_dir, "%03d-%s-%s" % (index, kind, os.path.basename(src)))
    with open(out, "wb") as f:
        f.write(damaged)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir")
    ap.add_argument("--count", type=int, default=300)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--models", default="/usr/share/assimp/models")
    ap.add_argument("--pristine", action="store_true", help="write every chosen source once, undamaged")
    args = ap.parse_args()

    sources = find_sources(args.models)
    formats = [f for f in FORMATS if sources[f]]
    missing = [f for f in FORMATS if not sources[f]]
    if missing:
        print("no source files for: %s" % " ".join(missing), file=sys.stderr)
    if not formats:
        sys.exit("no model files under %s" % args.models)
    order = {}
    for f in formats:
        order[f] = list(sources[f])
        random.Random("%d:order:%s" % (args.seed, f)).shuffle(order[f])

    counts = collections.Counter()
    log = []
    if args.pristine:
        jobs = [(f, "none", src) for f in formats for src in sources[f]]
    else:
        jobs = []
        for i in range(args.count):
            f = formats[i % len(formats)]
            j = i // len(formats)  # this format's j-th file
            jobs.append((f, KINDS[j % len(KINDS)], order[f][j % len(order[f])]))
    for index, (fmt, kind, src) in enumerate(jobs):
        with open(src, "rb") as fh:
            data = fh.read()
        if kind == "none":
            damaged, note = data, "undamaged"
        else:
            rng = random.Random("%d:%d:%s:%s" % (args.seed, index, kind, os.path.relpath(src, args.models)))
            damaged, note = DAMAGE[kind](rng, fmt, data)
        out = write_output(args.outdir, fmt, index, kind, src, damaged)
        counts[(fmt, kind)] += 1
        log.append("%s\t%s\t%s\n" % (os.path.relpath(out, args.outdir), os.path.relpath(src, args.models), note))
    os.makedirs(args.outdir, exist_ok=True)
    with open(os.path.join(args.outdir, "damage-log.tsv"), "w") as fh:
        fh.write("output\tsource\tdamage\n")
        fh.writelines(log)

    kinds = ["none"] if args.pristine else KINDS
    print("%-6s %s %6s" % ("format", " ".join("%9s" % k for k in kinds), "total"))
    for f in formats:
        row = [counts[(f, k)] for k in kinds]
        print("%-6s %s %6d" % (f, " ".join("%9d" % n for n in row), sum(row)))
    print("%-6s %s %6d" % ("total", " ".join("%9d" % sum(counts[(f, k)] for f in formats) for k in kinds),
                           sum(counts.values())))
    print("wrote %d files to %s (log: %s)" % (sum(counts.values()), args.outdir,
                                                os.path.join(args.outdir, "damage-log.tsv")))


if __name__ == "__main__":
    main()
