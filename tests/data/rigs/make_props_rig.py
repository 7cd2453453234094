#!/usr/bin/env python3
"""Writes props_rig.gltf: a small Mixamo-named biped made of boxes, each
skinned wholly to its joint, with rigid parts that have no skin: a spear
under the right hand's node (turned and moved by its own node transform),
a helmet under the head's, a crate under no joint at all, well away from
the body; and beside the armature, under no joint but close to the body,
a lance standing by the left hand (its foot on the floor by the left
foot) and a cape behind the back. A hat skinned to a slot joint that
hangs from the armature, not from the head (as Soldier's HelmetSlot), and
a control rig beside the bones (Ctrl_ joints weighting nothing, their
legs reaching forward along the floor, as Paladin's FK controls). Colours:
the body's material a base colour (linear 0.5 0.1 0.1), the helmet's a
gold one (1 0.6 0.1) whose texture, missing_gold.png, is not there, the
lance red and blue by vertex colours; the rest without a material. Run from
this folder: python3 make_props_rig.py (the test reads the output)."""
import base64, json, math, struct

J = [  # name, parent, global head (metres, T-pose, Y up, facing +Z)
    ("Hips", None, (0, 1.0, 0)), ("Spine", "Hips", (0, 1.1, 0)), ("Spine1", "Spine", (0, 1.2, 0)),
    ("Spine2", "Spine1", (0, 1.3, 0)), ("Neck", "Spine2", (0, 1.45, 0)), ("Head", "Neck", (0, 1.55, 0)),
    ("HeadTop_End", "Head", (0, 1.75, 0))]
for s, x in (("Left", 1), ("Right", -1)):
    J += [(s + "Shoulder", "Spine2", (0.05 * x, 1.4, 0)), (s + "Arm", s + "Shoulder", (0.18 * x, 1.4, 0)),
          (s + "ForeArm", s + "Arm", (0.45 * x, 1.4, 0)), (s + "Hand", s + "ForeArm", (0.7 * x, 1.4, 0)),
          (s + "HandMiddle1", s + "Hand", (0.8 * x, 1.4, 0)), (s + "HandMiddle_End", s + "HandMiddle1", (0.88 * x, 1.4, 0)),
          (s + "UpLeg", "Hips", (0.1 * x, 0.95, 0)), (s + "Leg", s + "UpLeg", (0.1 * x, 0.52, 0)),
          (s + "Foot", s + "Leg", (0.1 * x, 0.08, 0)), (s + "ToeBase", s + "Foot", (0.1 * x, 0.02, 0.12)),
          (s + "Toe_End", s + "ToeBase", (0.1 * x, 0.02, 0.2))]
# unweighted controls, as a rigging add-on makes them: a chain from a
# master control, two "legs" lying forward along the floor
J += [("Ctrl_Master", None, (0, 0.0, 0)), ("Ctrl_Hips", "Ctrl_Master", (0, 0.05, 0))]
for s, x in (("Left", 1), ("Right", -1)):
    J += [("Ctrl_UpLeg_FK_" + s, "Ctrl_Hips", (0.1 * x, 0.05, 0.1)), ("Ctrl_Leg_FK_" + s, "Ctrl_UpLeg_FK_" + s, (0.1 * x, 0.05, 0.5)),
          ("Ctrl_Foot_FK_" + s, "Ctrl_Leg_FK_" + s, (0.1 * x, 0.05, 0.9))]
J += [("HatSlot", None, (0, 1.8, 0))]
CONTROLS = [j[0] for j in J if j[0].startswith("Ctrl_")]
name = [j[0] for j in J]
head = {j[0]: j[2] for j in J}
parent = {j[0]: j[1] for j in J}
children = {n: [c for c in name if parent[c] == n] for n in name}

def box(lo, hi):
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    v = [(x, y, z) for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]
    f = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1),
         (2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]
    return v, f

# the body: a box along each bone, from its head to its first child's
bv, bf, bj = [], [], []
for i, n in enumerate(name):
    if not children[n] or n in CONTROLS:
        continue
    a, b = head[n], head[children[n][0]]
    t = 0.09 if n.startswith(("Hips", "Spine")) else 0.05 if n in ("Neck", "Head") else 0.035
    lo = [min(a[k], b[k]) - t for k in range(3)]
    hi = [max(a[k], b[k]) + t for k in range(3)]
    v, f = box(lo, hi)
    base = len(bv)
    bv += v
    bf += [(p + base, q + base, r + base) for p, q, r in f]
    bj += [i] * len(v)

buf = bytearray()
views, accessors = [], []
def add(data, target=None):
    while len(buf) % 4:
        buf.append(0)
    views.append({"buffer": 0, "byteOffset": len(buf), "byteLength": len(data), **({"target": target} if target else {})})
    buf.extend(data)
    return len(views) - 1
def accessor(view, ctype, count, typ, mn=None, mx=None):
    a = {"bufferView": view, "componentType": ctype, "count": count, "type": typ}
    if mn is not None:
        a["min"], a["max"] = mn, mx
    accessors.append(a)
    return len(accessors) - 1
def positions(v):
    mn = [min(p[k] for p in v) for k in range(3)]
    mx = [max(p[k] for p in v) for k in range(3)]
    return accessor(add(b"".join(struct.pack("<3f", *p) for p in v), 34962), 5126, len(v), "VEC3", mn, mx)
def indices(f):
    flat = [i for t in f for i in t]
    return accessor(add(struct.pack("<%dH" % len(flat), *flat), 34963), 5123, len(flat), "SCALAR")

meshes = []
body_pos = positions(bv)
body_idx = indices(bf)
jnt = accessor(add(b"".join(struct.pack("<4H", j, 0, 0, 0) for j in bj), 34962), 5123, len(bj), "VEC4")
wgt = accessor(add(b"".join(struct.pack("<4f", 1, 0, 0, 0) for _ in bj), 34962), 5126, len(bj), "VEC4")
meshes.append({"name": "Body", "primitives": [{"attributes": {"POSITION": body_pos, "JOINTS_0": jnt, "WEIGHTS_0": wgt},
                                                "indices": body_idx, "material": 0}]})
materials = [{"name": "Skin", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.1, 0.1, 1]}},
             {"name": "Gold", "pbrMetallicRoughness": {"baseColorFactor": [1.0, 0.6, 0.1, 1], "baseColorTexture": {"index": 0}}}]
def rigid(mesh_name, lo, hi, extra=None):
    v, f = box(lo, hi)
    prim = {"attributes": {"POSITION": positions(v)}, "indices": indices(f)}
    if extra:
        extra(prim, v)
    meshes.append({"name": mesh_name, "primitives": [prim]})
    return len(meshes) - 1
def gold(prim, v):  # the helmet: the gold material, its texture missing
    prim["material"] = 1
    prim["attributes"]["TEXCOORD_0"] = accessor(add(b"".join(struct.pack("<2f", 0.5, 0.5) for _ in v), 34962), 5126, len(v), "VEC2")
def red_blue(prim, v):  # the lance: red at the floor, blue at the top
    prim["attributes"]["COLOR_0"] = accessor(add(b"".join(struct.pack("<4f", *((1, 0, 0, 1) if p[1] < 1 else (0, 0, 1, 1)))
                                                         for p in v), 34962), 5126, len(v), "VEC4")
spear = rigid("Spear", (-0.012, -0.9, -0.012), (0.012, 0.7, 0.012))   # along its node's Y
helmet = rigid("Helmet", (-0.11, -0.04, -0.11), (0.11, 0.1, 0.11), gold)
crate = rigid("Crate", (-0.1, 0, -0.1), (0.1, 0.2, 0.1))
lance = rigid("Lance", (0.77, 0.0, 0.09), (0.79, 2.0, 0.11), red_blue)  # standing by the left hand
cape = rigid("Cape", (-0.15, 0.9, -0.14), (0.15, 1.38, -0.12))  # behind the back

# the hat: skinned wholly to HatSlot
hv, hf = box((-0.08, 1.76, -0.08), (0.08, 1.86, 0.08))
hat_j = accessor(add(b"".join(struct.pack("<4H", name.index("HatSlot"), 0, 0, 0) for _ in hv), 34962), 5123, len(hv), "VEC4")
hat_w = accessor(add(b"".join(struct.pack("<4f", 1, 0, 0, 0) for _ in hv), 34962), 5126, len(hv), "VEC4")
meshes.append({"name": "Hat", "primitives": [{"attributes": {"POSITION": positions(hv), "JOINTS_0": hat_j,
                                                              "WEIGHTS_0": hat_w}, "indices": indices(hf)}]})
hat = len(meshes) - 1

ibm = b""
for n in name:  # inverse bind matrices: column-major translations by -head
    x, y, z = head[n]
    ibm += struct.pack("<16f", 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -x, -y, -z, 1)
ibm_acc = accessor(add(ibm), 5126, len(name), "MAT4")

nodes = []
for n in name:
    p = head[parent[n]] if parent[n] else (0, 0, 0)
    nodes.append({"name": n if n in CONTROLS or n == "HatSlot" else "mixamorig:" + n, "translation": [head[n][k] - p[k] for k in range(3)],
                  "children": [name.index(c) for c in children[n]]})
def node(d):
    nodes.append(d)
    return len(nodes) - 1
s = math.sqrt(0.5)
# the spear lies forward (+Z) through the right fist: its node turns it 90 degrees about X and moves it
nodes[name.index("RightHand")]["children"].append(
    node({"name": "Spear", "mesh": spear, "translation": [-0.05, 0.0, 0.03], "rotation": [s, 0, 0, s]}))
nodes[name.index("Head")]["children"].append(node({"name": "Helmet", "mesh": helmet, "translation": [0, 0.12, 0]}))
body = node({"name": "Body", "mesh": 0, "skin": 0})
crate_node = node({"name": "Crate", "mesh": crate, "translation": [0.9, 0, -0.7]})
lance_node = node({"name": "Lance", "mesh": lance})
cape_node = node({"name": "Cape", "mesh": cape})
hat_node = node({"name": "Hat", "mesh": hat, "skin": 0})
armature = node({"name": "Armature", "children": [0, name.index("Ctrl_Master"), name.index("HatSlot")]})
gltf = {
    "asset": {"version": "2.0", "generator": "skinplay tests/data/rigs/make_props_rig.py"},
    "scene": 0, "scenes": [{"nodes": [armature, body, crate_node, lance_node, cape_node, hat_node]}],
    "nodes": nodes, "meshes": meshes, "materials": materials,
    "textures": [{"source": 0}], "images": [{"uri": "missing_gold.png"}],
    "skins": [{"joints": list(range(len(name))), "inverseBindMatrices": ibm_acc, "skeleton": 0}],
    "accessors": accessors, "bufferViews": views,
    "buffers": [{"byteLength": len(buf), "uri": "data:application/octet-stream;base64," +
                 base64.b64encode(bytes(buf)).decode()}],
}
with open("props_rig.gltf", "w") as f:
    json.dump(gltf, f, indent=1)
    f.write("\n")
