#!/usr/bin/env python3
"""How computed weights deform against the artist's (issue 46), on the
MakeHuman body (assets/makehuman), CMU 02's skeleton, the hand-made bind
pose tests/data/makehuman_apose.amc, 24 frames spread over each of the walk
(02_01) and the kick, skinned with LBS by skintool skin:
  - the largest lengthening of any triangle edge, in % of the body's height;
  - the edges ever past twice their bind length, and the largest ratio;
  - the mean distance of each vertex from where the artist's weights put
    it, in % of the height.
Run from the repository after make: python3 tests/weights_figures.py
[BUILD_DIR] (about a minute and a half; prints one row a clip for the
computed weights and the artist's).

With RIG files (python3 tests/weights_figures.py [BUILD_DIR] RIG.glb...):
rigged bodies nobody here made, each bound in its own pose (no hand-made
bind pose) to the same skeleton and clips, with computed weights and with
its own. Per clip and weights the quality gate's tear figures, as `skintool
bind --motion=M.amc --report` gives them (the range of motion and the clip:
the worst edge's ratio to its bind length, the edges ever past 2x, the
largest lengthening in % of the skeleton's extent), and the mean distance
of the computed weights' deformation from the rig's own over the same 24
frames (LBS), in % of the body's height as its own weights pose it in the
walk's first of them (a minute or two a rig)."""
import math, os, re, shutil, subprocess, sys, tempfile

ARGS = [a for a in sys.argv[1:] if not a.lower().endswith((".glb", ".gltf", ".fbx", ".dae"))]
RIGS = [a for a in sys.argv[1:] if a not in ARGS]
BUILD = ARGS[0] if ARGS else "build"
TOOL = os.path.join(BUILD, "skintool")
ASF = "assets/cmu/02.asf"
BIND = "tests/data/makehuman_apose.amc"
BODY = ["assets/makehuman/base.obj", "--rig", "assets/makehuman/default.mhskel", "--bind-pose", BIND]
CLIPS = ["assets/cmu/02_01.amc", "assets/cmu/kick.amc"]
work = tempfile.mkdtemp(prefix="skp_weights_")


def frames_of(amc, count=24):
    numbers = [int(l) for l in open(amc) if l.strip().isdigit()]
    return [numbers[i * (len(numbers) - 1) // (count - 1)] for i in range(count)]


def skin(amc, frame, weights, out, body=None):
    subprocess.run([TOOL, "skin", ASF, amc] + (body or BODY) + ["--frame=%d" % frame, "--algo=lbs", "-q", "--force",
                                                                 "-o", out] + weights, check=True)


def read_obj(path):
    verts, faces = [], []
    for line in open(path):
        if line.startswith("v "):
            verts.append(tuple(map(float, line.split()[1:4])))
        elif line.startswith("f "):
            faces.append([int(x.split("/")[0]) - 1 for x in line.split()[1:]])
    return verts, faces


def posed(tag, weights, body=None):
    out = {}
    for clip in CLIPS:
        out[clip] = []
        for k, n in enumerate(frames_of(clip)):
            path = os.path.join(work, "%s_%s_%d.obj" % (tag, os.path.basename(clip), k))
            skin(clip, n, weights, path, body)
            out[clip].append(path)
    return out


def mean_distance(pos, ref, height):
    """The mean distance of each vertex from its reference, a fraction of the height."""
    return sum(math.dist(p, q) for p, q in zip(pos, ref)) / len(pos) / height


def gate_tears(rig, clip, weights):
    """The gate's tear figures for the rig in the range of motion and the clip."""
    run = subprocess.run([TOOL, "bind", ASF, rig, "--motion=" + clip, "--report", "-o",
                          os.path.join(work, "weights.csv")] + weights, capture_output=True, text=True)
    tears = re.search(r"tears: worst edge ([0-9.]+) times .*?, ([0-9]+) edges ever past 2x", run.stderr)
    grow = re.search(r"grow: an edge longer by ([0-9.]+)% of the extent", run.stderr)
    if run.returncode not in (0, 1) or not tears or not grow:
        sys.exit("%s: skintool bind said:\n%s" % (rig, run.stderr))
    verdict = "refused by the gate" if run.returncode else "passes the gate"
    return float(tears.group(1)), int(tears.group(2)), float(grow.group(1)), verdict


def rig_figures(rig):
    """One row a clip and weights for a rigged file bound in its own pose."""
    own = posed("own", ["--weights=mesh"], [rig])
    mine = posed("computed", [], [rig])
    ys = [p[1] for p in read_obj(own[CLIPS[0]][0])[0]]
    height = max(ys) - min(ys)
    for clip in CLIPS:
        dist = []
        for k, path in enumerate(mine[clip]):
            pos, ref = read_obj(path)[0], read_obj(own[clip][k])[0]
            dist.append(mean_distance(pos, ref, height))
        for tag, weights in (("computed", []), ("own", ["--weights=mesh"])):
            ratio, doubled, grow, verdict = gate_tears(rig, clip, weights)
            far = "; mean distance to its own %.2f%% of height" % (100 * sum(dist) / len(dist)) if tag == "computed" else ""
            print("%-20s %-8s %-10s worst edge %.2fx, %d edges past 2x, longer by %.2f%% of the extent, %s%s" %
                  (os.path.basename(rig), tag, os.path.basename(clip), ratio, doubled, grow, verdict, far))


def main():
    if RIGS:
        for rig in RIGS:
            rig_figures(rig)
        return
    bind_obj = os.path.join(work, "bind.obj")
    skin(BIND, 1, ["--weights=mesh"], bind_obj)
    bind, faces = read_obj(bind_obj)
    ys = [p[1] for p in bind]
    height = max(ys) - min(ys)
    edges = sorted({(min(f[i], f[(i + 1) % len(f)]), max(f[i], f[(i + 1) % len(f)])) for f in faces
                    for i in range(len(f))})
    bind_len = [math.dist(bind[a], bind[b]) for a, b in edges]
    artist = posed("artist", ["--weights=mesh"])
    for tag, weights in (("computed", []), ("artist", ["--weights=mesh"])):
        mine = artist if tag == "artist" else posed(tag, weights)
        for clip in CLIPS:
            worst, ratio, doubled, dist = 0.0, 0.0, set(), []
            for k, path in enumerate(mine[clip]):
                pos, _ = read_obj(path)
                for i, (a, b) in enumerate(edges):
                    if bind_len[i] <= 1e-9:
                        continue
                    length = math.dist(pos[a], pos[b])
                    worst = max(worst, (length - bind_len[i]) / height)
                    ratio = max(ratio, length / bind_len[i])
                    if length > 2 * bind_len[i]:
                        doubled.add(i)
                ref, _ = read_obj(artist[clip][k])
                dist.append(mean_distance(pos, ref, height))
            print("%-8s %-10s lengthening %.2f%% of height, %d edges past 2x, largest ratio %.1fx, "
                  "mean distance to the artist's %.2f%%" % (tag, os.path.basename(clip), 100 * worst, len(doubled),
                                                           ratio, 100 * sum(dist) / len(dist)))


try:
    main()
finally:
    shutil.rmtree(work, ignore_errors=True)
