#!/usr/bin/env python3
"""Damage sweep (issue 45): damaged copies of a packed show, class by
class, through skinplay, skintool info and skintool repair, counted.

Two images of one show (assets/cmu/02.asf, 02_01 and kick): compressed (the
default) and --raw. The reference is skinplay --platform none --pose-digest
on the undamaged image. Each damaged copy is played the same way, given to
`skintool info`, and repaired on a copy (`skintool repair`). A case is:
  identical   exit 0, the reference's pose digest, no recovery logged
  rebuilt     exit 0, the reference's digest, a recovery logged (a block
              rebuilt from parity or its copy, the header from its copy)
  reason      a non-zero exit or another digest, with a line naming a damaged
              block, a refusal with its reason, a clip skipped, frames held,
              the storage ending early
  WRONG       exit 0, another digest, nothing naming the damage (must be 0)
  crash       killed by a signal, timed out, or a non-zero exit with no
              reason (must be 0)
"repaired" counts the cases where repair exited 0 and the image then
played as the reference (in brackets: byte-identical to the pack); a
repair that exits 0, changes the file and leaves it playing otherwise is a
failure too (one that changes nothing, every block checking, is neither).

The pose digest covers the joints of every pose shown, not the body's
vertices: damage to the skeleton or bind blocks that nothing names is
listed as "silent" (none was found when this was written).

Usage: python3 tests/damage_sweep.py [BUILD_DIR] [--every K] [--jobs N]
  --every K  every K-th block for the single-block classes (default 2;
             1: every block, about twice the time)
Offsets and bits come from a fixed seed; pack draws a new image id each
run, which changes no verdict. Exit 1 when any case is WRONG, crash or a
wrong repair (listed, the damaged file kept in BUILD_DIR/damage-sweep/);
every case's verdicts in BUILD_DIR/damage-sweep/cases.tsv.
"""
import concurrent.futures, hashlib, os, random, re, shutil, struct, subprocess, sys, time, zlib

args = sys.argv[1:]
BUILD, EVERY, JOBS = "build", 2, 2
while args:
    a = args.pop(0)
    if a == "--every":
        EVERY = int(args.pop(0))
    elif a == "--jobs":
        JOBS = int(args.pop(0))
    else:
        BUILD = a
TOOL, PLAY = os.path.join(BUILD, "skintool"), os.path.join(BUILD, "skinplay")
OUT = os.path.join(BUILD, "damage-sweep")
SHOW = ["assets/cmu/02.asf", "assets/cmu/02_01.amc", "assets/cmu/kick.amc", "--sequence", "45"]
B = 4096
t_start = time.time()


def run(cmd, timeout=60):
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout)
        return p.returncode, p.stdout.decode("utf-8", "replace")
    except subprocess.TimeoutExpired:
        return "timeout", ""


def play(path):
    rc, log = run([PLAY, "--image", path, "--platform", "none", "--pose-digest"])
    m = re.search(r"^poses: .* digest ([0-9a-f]+)$", log, re.M)
    return rc, (m.group(1) if m else None), log


def seal(blk):
    return blk[:B - 4] + struct.pack("<I", zlib.crc32(bytes(blk[:B - 4])))


class Image:
    def __init__(self, name, path):
        self.name, self.path = name, path
        self.data = open(path, "rb").read()
        h = self.data[24:24 + 168]
        assert h[:8] == b"SKPIMAGE" and struct.unpack_from("<I", h, 12)[0] == B
        self.n = struct.unpack_from("<I", h, 16)[0]
        self.D, self.P = struct.unpack_from("<II", h, 116)
        self.dir_first, self.dir_count = struct.unpack_from("<II", h, 68 + 24)
        self.bind_last = sum(struct.unpack_from("<II", h, 68 + 12)) - 1
        self.kind = [self.data[b * B + 20] if not self.D <= b < self.D + self.P else 0 for b in range(self.n)]
        rc, self.digest, log = play(path)
        assert rc == 0 and self.digest, log

    def block(self, d, b):
        return bytearray(d[b * B:(b + 1) * B])

    def put(self, d, b, blk):
        d[b * B:(b + 1) * B] = blk


def forge_deep(img, d, b):
    """A forger who knows version 7: block b resealed, its leaf, the digest
    block, the root in both headers and the parity made good again."""
    d[b * B:(b + 1) * B] = seal(d[b * B:(b + 1) * B])
    H = img.dir_first + img.dir_count
    per = (B - 28) // 16
    db = H + b // per
    leaf = lambda k: hashlib.sha256(bytes(d[k * B:(k + 1) * B])).digest()[:16]
    o = db * B + 24 + (b % per) * 16
    d[o:o + 16] = leaf(b)
    d[db * B:(db + 1) * B] = seal(d[db * B:(db + 1) * B])
    root = hashlib.sha256(b"".join(leaf(k) for k in range(H, img.D))).digest()
    last = img.n - 1
    for blk, at in ((0, 24), (last, B - 172)):
        o = blk * B + at
        d[o + 132:o + 164] = root
        d[o + 164:o + 168] = struct.pack("<I", zlib.crc32(bytes(d[o:o + 164])))
        d[blk * B:(blk + 1) * B] = seal(d[blk * B:(blk + 1) * B])
    for g in {0, b % img.P, db % img.P}:
        x = bytearray(B)
        for k in range(g, img.D, img.P):
            x = bytearray(p ^ q for p, q in zip(x, d[k * B:(k + 1) * B]))
        d[(img.D + g) * B:(img.D + g + 1) * B] = x


def flip(d, b, rng, lo=0, hi=B):
    o = b * B + rng.randrange(lo, hi)
    d[o] ^= 1 << rng.randrange(8)
    return o


def cases_for(img, other):
    """(class, description, bytes) for one image."""
    o, n, D, P = img.data, img.n, img.D, img.P
    rng = random.Random(45)
    spread = range(0, n, EVERY)
    for b in spread:
        d = bytearray(o); at = flip(d, b, rng)
        yield "one block: a bit flipped", f"block {b}: byte {at} bit flipped", d
    for b in spread:
        d = bytearray(o); d[b * B:(b + 1) * B] = bytes(B)
        yield "one block: zeroed", f"block {b} zeroed", d
    for b in spread:
        if D <= b < D + P:
            continue  # parity has no CRC: the flips above
        d = bytearray(o); at = flip(d, b, rng, 24, B - 4); d[b * B:(b + 1) * B] = seal(d[b * B:(b + 1) * B])
        yield "one block: forged (CRC made good)", f"block {b}: byte {at} changed, CRC resealed", d
    for b in range(0, n - 1, 2 * EVERY):
        d = bytearray(o); a1 = flip(d, b, rng); a2 = flip(d, b + 1, rng)
        yield "two adjacent blocks bad", f"blocks {b},{b + 1}: bytes {a1},{a2} flipped", d
    for m in list(range(P, D, P)) + [D]:
        for how in (0, 1):
            d = bytearray(o)
            if how:
                flip(d, 0, rng, 24, 192); d[m * B:(m + 1) * B] = bytes(B)
            else:
                d[0:B] = bytes(B); flip(d, m, rng)
            yield "block 0 + another of parity group 0", f"block 0 {'flipped' if how else 'zeroed'}, block {m} {'zeroed' if how else 'flipped'}", d
    for k in range(1, 9):
        d = bytearray(o); d[0:k * B] = other.data[0:k * B]
        yield "blocks 0..k-1 from another pack (k 1..8)", f"blocks 0..{k - 1} from another pack, same sequence", d
    for b in range(1, n, 5 * EVERY):
        d = bytearray(o); d[b * B:(b + 1) * B] = other.data[b * B:(b + 1) * B]
        yield "one block from another pack", f"block {b} from another pack, same sequence", d
    thirds = [None] + [b for b in (1, 40, 100, D - 2, D + 3) if b % P]
    for third in thirds:
        for h0 in ("zeroed", "flipped"):
            for hc in ("zeroed", "flipped", "cut off"):
                d = bytearray(o)
                if h0 == "zeroed":
                    d[0:B] = bytes(B)
                else:
                    flip(d, 0, rng, 24, 192)
                if hc == "zeroed":
                    d[(n - 1) * B:] = bytes(B)
                elif hc == "flipped":
                    flip(d, n - 1, rng, B - 172, B - 4)
                else:
                    del d[(n - 1) * B:]
                if third is not None:
                    flip(d, third, rng)
                yield "block 0 + header copy lost", f"block 0 {h0}, header copy {hc}" + (f", block {third} flipped" if third else ""), d
    for size in sorted(set([k * B for k in range(1, n, max(1, n // 20))] + [k * B + rng.randrange(1, B) for k in range(0, n, max(1, n // 10))]
                           + [D * B, (D + 1) * B, (D + P) * B, (n - 1) * B, n * B - 1, n * B - 100])):
        yield "truncated", f"truncated to {size} bytes", bytearray(o[:size])
    # a clip's quantisation (--raw: f32 min, step a dof) or codec header
    # (u16 tracks, u16 segment frames, f32 base, f32 step, u8 bits a track)
    for c in (0, 1):
        qb = next(b for b in range(n) if img.kind[b] == 5 and o[b * B + 22] == c)
        for dof in (3, 20, 61):
            for field, val in (("min", 2e6), ("min", -3e7), ("min", 1e30), ("min", float("inf")), ("min", float("nan")), ("step", -1e-3), ("step", 1e30)):
                d = bytearray(o)
                at = qb * B + 24 + (8 * dof if img.name == "raw" else 4 + 9 * dof) + (4 if field == "step" else 0)
                d[at:at + 4] = struct.pack("<f", val)
                forge_deep(img, d, qb)
                yield "rotation out of range (forged with digests, root, parity)", f"clip {c} dof {dof} {field} = {val} (block {qb})", d
    yield "wrong-length or zero-filled slot", "empty file", bytearray()
    for size in (1, 100, B - 1, B, len(o)):
        yield "wrong-length or zero-filled slot", f"{size} zero bytes", bytearray(size)
    yield "wrong-length or zero-filled slot", "the image's length of random bytes", bytearray(rng.randbytes(len(o)))
    for pad in (1, 100, B, 65536, 1 << 20):
        yield "wrong-length or zero-filled slot", f"{pad} zero bytes after the image", bytearray(o + bytes(pad))
    d = bytearray(o + rng.randbytes(1000)); d[0:B] = bytes(B)
    yield "wrong-length or zero-filled slot", "1000 random bytes after the image, block 0 zeroed", d
    d = bytearray(o + bytes(1 << 20)); d[0:B] = bytes(B)
    yield "wrong-length or zero-filled slot", "1 MiB of zeros after the image, block 0 zeroed", d
    yield "wrong-length or zero-filled slot", "512 zero bytes before the image", bytearray(bytes(512) + o)
    for k in sorted(set([1, 2, D // 2, D - 1, D, D + P, n - 1] + list(range(4, n, max(1, n // 8))))):
        yield "wrong-length or zero-filled slot", f"zeros from block {k} to the end (a write cut short)", bytearray(o[:k * B] + bytes((n - k) * B))


RECOVERED = re.compile(r"rebuilt from parity|from its copy|header read from|header rebuilt|storage ends")
REASONS = re.compile(r"refused: \S|clip \S+ skipped|holding frame|held over bad blocks|image truncated|storage ends|"
                     r"no valid image|cannot play|holding the bind pose")


def named_blocks(log):
    got = set()
    for m in re.finditer(r"\bblocks? (\d+)(?:\.\.(\d+))?", log):
        lo = int(m.group(1)); hi = int(m.group(2) or lo)
        got.update(range(lo, min(hi, lo + 100000) + 1))
    return got


def judge(img, job):
    cls, desc, d, idx = job
    path = os.path.join(OUT, f"case{idx}.skn")
    with open(path, "wb") as f:
        f.write(d)
    o = img.data
    damaged = {b for b in range(img.n) if d[b * B:(b + 1) * B] != o[b * B:(b + 1) * B]}
    rc, digest, log = play(path)
    irc, _ = run([TOOL, "info", path])
    rep = path + ".rep.skn"
    shutil.copyfile(path, rep)
    rrc, rlog = run([TOOL, "repair", rep])
    repaired, byte_same, repair_wrong = 0, 0, ""
    if rrc == 0:
        r = open(rep, "rb").read()
        byte_same = r == o or (r[:len(o)] == o and r[len(o):] == bytes(d[len(o):]))
        if r == bytes(d) and not byte_same:
            pass  # "nothing to repair": the blocks check (a forger's meaning, refused by acceptance)
        elif byte_same:
            repaired = 1
        else:
            prc, pdig, _ = play(rep)
            if prc == 0 and pdig == img.digest:
                repaired = 1
            else:
                repair_wrong = f"repair exited 0, then skinplay exit {prc} digest {pdig}"
    named = named_blocks(log) & damaged
    if rc == "timeout" or (isinstance(rc, int) and (rc < 0 or rc >= 128)):
        verdict = "crash"
    elif rc == 0 and digest == img.digest:
        verdict = "rebuilt" if RECOVERED.search(log) else "identical"
    elif named or REASONS.search(log):
        verdict = "reason"
    elif rc == 0:
        verdict = "WRONG"
    else:
        verdict = "crash"  # a non-zero exit with no reason
    silent = verdict == "identical" and any(1 <= b <= img.bind_last for b in damaged) and not named
    keep = verdict in ("WRONG", "crash") or repair_wrong or silent
    if keep:
        with open(path + ".log", "w") as f:
            f.write(f"{img.name}: {cls}: {desc}\nskinplay exit {rc}\n{log}\ninfo exit {irc}\nrepair exit {rrc}\n{rlog}\n{repair_wrong}\n")
    else:
        os.unlink(path)
    os.unlink(rep)
    return cls, img.name, desc, verdict, irc, rrc, repaired, byte_same, repair_wrong, silent, path


def main():
    shutil.rmtree(OUT, ignore_errors=True)
    os.makedirs(OUT)
    images = {}
    for name, extra in (("compressed", []), ("raw", ["--raw"])):
        for k in ("", "_other"):
            p = os.path.join(OUT, f"{name}{k}.skn")
            rc, log = run([TOOL, "pack", "-q"] + extra + SHOW + ["-o", p], timeout=300)
            if rc != 0:
                sys.exit(f"damage-sweep: pack failed:\n{log}")
        images[name] = (Image(name, os.path.join(OUT, f"{name}.skn")), Image(name, os.path.join(OUT, f"{name}_other.skn")))
        img = images[name][0]
        print(f"damage-sweep: {name}: {img.n} blocks, {img.D} data, {img.P} parity groups, reference digest {img.digest}")
    # the deep forger checked: a change within range passes every check
    img = images["raw"][0]
    d = bytearray(img.data)
    qb = next(b for b in range(img.n) if img.kind[b] == 5)
    d[qb * B + 24 + 8 * 20 + 4] ^= 1
    forge_deep(img, d, qb)
    p = os.path.join(OUT, "forger_check.skn")
    open(p, "wb").write(d)
    irc, ilog = run([TOOL, "info", p])
    if irc != 0:
        sys.exit(f"damage-sweep: the forger's image does not pass info (the forge is wrong):\n{ilog}")
    jobs = []
    for name, (img, other) in images.items():
        for cls, desc, d in cases_for(img, other):
            if d == img.data:
                continue  # no byte changed (another pack's parity block of an even group: the ids cancel)
            jobs.append((img, (cls, desc, bytes(d), len(jobs))))
    print(f"damage-sweep: {len(jobs)} cases, {JOBS} at a time")
    results = []
    with concurrent.futures.ThreadPoolExecutor(JOBS) as ex:
        for r in ex.map(lambda j: judge(*j), jobs):
            results.append(r)
    with open(os.path.join(OUT, "cases.tsv"), "w") as f:
        f.write("image\tclass\tcase\tverdict\tinfo exit\trepair exit\trepaired\tbyte-identical\n")
        for r in results:
            f.write(f"{r[1]}\t{r[0]}\t{r[2]}\t{r[3]}\t{r[4]}\t{r[5]}\t{r[6]}\t{int(bool(r[7]))}\n")
    classes = []
    for r in results:
        if r[0] not in classes:
            classes.append(r[0])
    print("\n| class | cases tried | identical | rebuilt | refused/held with a reason | wrong with exit 0 | crash or no reason | info exit != 0 | repaired to identical (byte-identical) |")
    print("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    tot = [0] * 8
    for c in classes:
        rs = [r for r in results if r[0] == c]
        row = [len(rs), sum(r[3] == "identical" for r in rs), sum(r[3] == "rebuilt" for r in rs), sum(r[3] == "reason" for r in rs),
               sum(r[3] == "WRONG" for r in rs), sum(r[3] == "crash" for r in rs), sum(r[4] != 0 for r in rs), sum(r[6] for r in rs)]
        bs = sum(bool(r[7]) for r in rs)
        tot = [a + b for a, b in zip(tot, row)]
        print(f"| {c} | " + " | ".join(map(str, row[:-1])) + f" | {row[-1]} ({bs}) |")
    bs = sum(bool(r[7]) for r in results)
    print("| **all** | " + " | ".join(f"**{v}**" for v in tot[:-1]) + f" | **{tot[-1]}** ({bs}) |\n")
    bad = [r for r in results if r[3] in ("WRONG", "crash") or r[8]]
    for r in bad:
        print(f"damage-sweep: FAILED: {r[1]}: {r[0]}: {r[2]}: {r[3]} {r[8]} (kept: {r[10]}, log {r[10]}.log)")
    for r in results:
        if r[9]:
            print(f"damage-sweep: silent (skeleton or bind damage, nothing named, poses identical): {r[1]}: {r[2]} ({r[10]})")
    print(f"damage-sweep: {len(results)} cases in {time.time() - t_start:.0f} s; "
          + ("FAILED" if bad else "no wrong result with exit 0, no crash, no wrong repair"))
    sys.exit(1 if bad else 0)


main()
