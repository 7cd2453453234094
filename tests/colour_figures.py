#!/usr/bin/env python3
"""Characters keep their colours (issue 44): the mean colour of a rigged
character's pixels as skinplay draws it, next to its own colours as Blender
shows them. Run from the repository after make:
  python3 tests/colour_figures.py [BUILD_DIR] RIG.glb|.fbx|.dae...
(a few seconds a rig; Blender is Debian's package `blender`).

skinplay: the rig packed with its own weights onto CMU 02 (the walk,
02_01), its first frame drawn headless with --background=transparent
(the character alone), lit as always. Blender: tests/blender_albedo.py, the
materials' base colours (factors, textures, vertex colours) unlit, rest
pose, from the front. Each: the mean sRGB colour of the pixels the
character covers whole (alpha 255). skinplay's light scales every channel
alike, so the colours agree when the three channels' ratios (skinplay over
Blender) agree: printed, with their spread (largest over smallest, less 1;
0% is the same hue). A rig skinplay refuses prints why."""
import os
import struct
import subprocess
import sys
import tempfile
import shutil
import zlib

ARGS = [a for a in sys.argv[1:] if not a.lower().endswith((".glb", ".gltf", ".fbx", ".dae"))]
RIGS = [a for a in sys.argv[1:] if a not in ARGS]
BUILD = ARGS[0] if ARGS else "build"
HERE = os.path.dirname(os.path.abspath(__file__))


def read_png(path):
    """8-bit RGBA, not interlaced (what skinplay and Blender write): width,
    height, and the rows' bytes."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit("%s: not a PNG" % path)
    at, idat, w = 8, b"", 0
    while at < len(data):
        n, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + n]
        if kind == b"IHDR":
            w, h, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if (depth, colour, interlace) != (8, 6, 0):
                sys.exit("%s: not 8-bit RGBA without interlace" % path)
        elif kind == b"IDAT":
            idat += body
        at += 12 + n
    raw, stride, rows, prev = zlib.decompress(idat), 4 * w, [], bytearray(4 * w)
    for y in range(h):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - 4] if i >= 4 else 0
            b, c = prev[i], prev[i - 4] if i >= 4 else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return w, h, rows


def mean_colour(path):
    """The mean sRGB colour of the fully covered pixels, and their count."""
    _, _, rows = read_png(path)
    total, n = [0, 0, 0], 0
    for line in rows:
        for i in range(0, len(line), 4):
            if line[i + 3] == 255:
                total[0] += line[i]
                total[1] += line[i + 1]
                total[2] += line[i + 2]
                n += 1
    return [t / n for t in total] if n else None, n


def skinplay_picture(rig, work):
    image, frames = os.path.join(work, "rig.skn"), os.path.join(work, "frames")
    pack = subprocess.run([os.path.join(BUILD, "skintool"), "pack", "-q", "assets/cmu/02.asf", "assets/cmu/02_01.amc",
                           "--mesh=" + rig, "--weights=mesh", "-o", image], capture_output=True, text=True)
    if pack.returncode:
        return None, pack.stderr.strip().splitlines()[-1] if pack.stderr.strip() else "pack failed"
    subprocess.run([os.path.join(BUILD, "skinplay"), "--image", image, "--platform", "surfaceless", "--size",
                    "540x960", "--hud", "off", "--frames", "1", "--background=transparent", "--out", frames],
                   check=True, capture_output=True)
    return os.path.join(frames, "frame_000001.png"), None


def blender_picture(rig, work):
    out = os.path.join(work, "blender.png")
    # Blender's Python finds its home by the python3 first on PATH: the
    # system's, whose numpy its importers need, not one a pyenv puts first
    env = dict(os.environ, PATH="/usr/bin:" + os.environ.get("PATH", ""))
    run = subprocess.run(["blender", "-b", "--factory-startup", "--python", os.path.join(HERE, "blender_albedo.py"),
                          "--", os.path.abspath(rig), out, "540x960"], capture_output=True, text=True, env=env)
    if not os.path.exists(out):
        sys.exit("%s: Blender drew nothing:\n%s%s" % (rig, run.stdout[-2000:], run.stderr[-2000:]))
    return out


def row(rig):
    work = tempfile.mkdtemp(prefix="skp_colour_")
    try:
        ours, refused = skinplay_picture(rig, work)
        if refused:
            return "%-22s refused: %s" % (os.path.basename(rig), refused)
        mine, n = mean_colour(ours)
        theirs, m = mean_colour(blender_picture(rig, work))
        if not mine or not theirs:
            return "%-22s no covered pixels (skinplay %d, Blender %d)" % (os.path.basename(rig), n, m)
        ratio = [a / b if b > 0 else float("inf") for a, b in zip(mine, theirs)]
        spread = max(ratio) / min(ratio) - 1 if min(ratio) > 0 else float("inf")
        return ("%-22s skinplay %3.0f %3.0f %3.0f (%d px)  Blender %3.0f %3.0f %3.0f (%d px)  "
                "ratios %.2f %.2f %.2f, spread %.0f%%" % ((os.path.basename(rig),) + tuple(mine) + (n,) +
                                                          tuple(theirs) + (m,) + tuple(ratio) + (100 * spread,)))
    finally:
        shutil.rmtree(work, ignore_errors=True)


if not RIGS:
    sys.exit(__doc__)
for r in RIGS:
    print(row(r), flush=True)
