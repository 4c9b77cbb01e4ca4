#!/usr/bin/env python3
# make_skinned_models.py: writes the glTF 2.0 files used as bundled data and as test data for
# skeletal (and morph) animation. The figure, walking_figure.gltf, is a skinned humanoid about
# 1.8 m tall (Y up, metres, facing +Z, feet on y = 0 at the bind pose) with 13 joints, one mesh of
# closed outward-facing parts (torso, head, legs, feet, arms) and two clips: "walk" (1 s, 25 keys,
# looping) and "idle" (2 s). The test files are bending_bar.gltf (two joints, clips "linear",
# "step" and "cubic"), the same bar as bending_bar_external.gltf + .bin and as bending_bar.glb,
# morph_cube.gltf (two morph targets, clip "inflate") and bad_weights.gltf (the bar with one vertex
# of all-zero weights and one with a NaN weight). Only the Python 3 standard library is used and
# the output is byte for byte the same on every run. Run it as
#     python3 tools/make_skinned_models.py --out-dir DIR [--figure-only | --tests-only]
# The bundled copies are refreshed with
#     python3 tools/make_skinned_models.py --figure-only --out-dir resources/models
#     python3 tools/make_skinned_models.py --tests-only --out-dir tests/data/anim
"""Writes deterministic skinned / morphed glTF 2.0 models (see the comment above)."""

import argparse
import base64
import json
import math
import struct
from pathlib import Path

FLOAT, UBYTE, USHORT, UINT = 5126, 5121, 5123, 5125
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}
FORMAT = {FLOAT: "f", UBYTE: "B", USHORT: "H", UINT: "I"}
GENERATOR = "spt tools/make_skinned_models.py"


def f32(x):
    """x rounded to the nearest float32 (as a Python float)."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


# ---------------------------------------------------------------------------------------------
# Small vector, quaternion and matrix helpers (matrices are column-major lists of 16, as glTF).


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def normalize(v):
    n = math.sqrt(dot(v, v))
    return (v[0] / n, v[1] / n, v[2] / n)


def quat_axis_angle(axis, degrees):
    """Unit quaternion (x, y, z, w) turning by degrees about a unit axis."""
    h = math.radians(degrees) / 2.0
    s = math.sin(h)
    return (axis[0] * s + 0.0, axis[1] * s + 0.0, axis[2] * s + 0.0, math.cos(h))  # no -0.0


def quat_mul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz)


def translation_matrix(t):
    return [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, t[0], t[1], t[2], 1]


def mat_mul(a, b):
    """a * b for column-major 4x4 matrices."""
    return [sum(a[k * 4 + r] * b[c * 4 + k] for k in range(4)) for c in range(4) for r in range(4)]


def affine_inverse(m):
    """Inverse of a column-major affine 4x4 matrix (last row 0 0 0 1)."""
    a = [[m[c * 4 + r] for c in range(3)] for r in range(3)]
    det = (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
           - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
           + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))
    inv = [[0.0] * 3 for _ in range(3)]
    for r in range(3):
        for c in range(3):
            r1, r2 = [i for i in range(3) if i != c]
            c1, c2 = [i for i in range(3) if i != r]
            minor = a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1]
            inv[r][c] = (-1) ** (r + c) * minor / det
    t = (m[12], m[13], m[14])
    it = [-sum(inv[r][k] * t[k] for k in range(3)) for r in range(3)]
    out = [0.0] * 16
    for c in range(3):
        for r in range(3):
            out[c * 4 + r] = inv[r][c]
    out[12], out[13], out[14], out[15] = it[0], it[1], it[2], 1.0
    return [v + 0.0 for v in out]  # no -0.0 in the output


def lerp_table(table, y):
    """Piecewise-linear interpolation of rows (y, v1, v2, ...) sorted by y, at y."""
    if y <= table[0][0]:
        return table[0][1:]
    for lo, hi in zip(table, table[1:]):
        if y <= hi[0]:
            u = (y - lo[0]) / (hi[0] - lo[0])
            return tuple(a + (b - a) * u for a, b in zip(lo[1:], hi[1:]))
    return table[-1][1:]


def clamp01(x):
    return max(0.0, min(1.0, x))


# ---------------------------------------------------------------------------------------------
# The binary buffer and its views and accessors.


class Buffer:
    def __init__(self):
        self.data = bytearray()
        self.views = []
        self.accessors = []

    def _pad(self):
        while len(self.data) % 4:
            self.data.append(0)

    def accessor(self, values, kind, component, target=None, bounds=False):
        """Appends values (scalars or tuples) as a new bufferView and accessor; returns its index.

        bounds: write min and max (the float32 values that the buffer holds)."""
        n = COMPONENTS[kind]
        rows = [(v,) if n == 1 and not isinstance(v, (tuple, list)) else tuple(v) for v in values]
        assert all(len(r) == n for r in rows), kind
        blob = b"".join(struct.pack("<%d%s" % (n, FORMAT[component]), *r) for r in rows)
        self._pad()
        view = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(blob)}
        if target is not None:
            view["target"] = target
        self.data += blob
        self._pad()
        self.views.append(view)
        acc = {"bufferView": len(self.views) - 1, "componentType": component,
               "count": len(rows), "type": kind}
        if bounds:
            stored = [[f32(x) if component == FLOAT else x for x in r] for r in rows]
            acc["min"] = [min(r[i] for r in stored) for i in range(n)]
            acc["max"] = [max(r[i] for r in stored) for i in range(n)]
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def floats(self, values, kind, bounds=False, target=None):
        return self.accessor(values, kind, FLOAT, target=target, bounds=bounds)

    def times(self, values):
        """Animation input: seconds, strictly increasing, with min and max."""
        assert all(b > a for a, b in zip(values, values[1:]))
        return self.floats(values, "SCALAR", bounds=True)


def document(buf, **parts):
    """The glTF JSON object: asset first, then the given top-level arrays, then buffer data."""
    doc = {"asset": {"version": "2.0", "generator": GENERATOR}}
    doc.update(parts)
    doc["accessors"] = buf.accessors
    doc["bufferViews"] = buf.views
    doc["buffers"] = [{"byteLength": len(buf.data)}]
    return doc


def json_text(doc):
    return json.dumps(doc, indent=1, allow_nan=False) + "\n"


def gltf_embedded(doc, data):
    doc = json.loads(json.dumps(doc))
    doc["buffers"][0]["uri"] = ("data:application/octet-stream;base64,"
                                + base64.b64encode(bytes(data)).decode("ascii"))
    return json_text(doc).encode("utf-8")


def gltf_external(doc, bin_name):
    doc = json.loads(json.dumps(doc))
    doc["buffers"][0]["uri"] = bin_name
    return json_text(doc).encode("utf-8")


def glb(doc, data):
    """Binary glTF: 12-byte header, JSON chunk padded with spaces, BIN chunk padded with zeros."""
    text = json.dumps(doc, separators=(",", ":"), allow_nan=False).encode("utf-8")
    text += b" " * (-len(text) % 4)
    data = bytes(data) + b"\0" * (-len(data) % 4)
    total = 12 + 8 + len(text) + 8 + len(data)
    return (struct.pack("<III", 0x46546C67, 2, total)
            + struct.pack("<II", len(text), 0x4E4F534A) + text
            + struct.pack("<II", len(data), 0x004E4942) + data)


# ---------------------------------------------------------------------------------------------
# Meshes: parts made of vertices (position, {joint: weight}) and triangles, each part closed.


class Part:
    def __init__(self, name):
        self.name = name
        self.positions = []
        self.weights = []
        self.triangles = []

    def vertex(self, p, w):
        self.positions.append(tuple(p))
        self.weights.append(dict(w))
        return len(self.positions) - 1

    def check_closed(self):
        """Every directed edge once, its reverse once (closed, consistently oriented 2-manifold),
        no vertex unused, and positive volume (outward-facing)."""
        directed = set()
        for t in self.triangles:
            assert len(set(t)) == 3, (self.name, t)
            for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
                assert (a, b) not in directed, (self.name, "edge used twice", a, b)
                directed.add((a, b))
        for a, b in directed:
            assert (b, a) in directed, (self.name, "open edge", a, b)
        used = {i for t in self.triangles for i in t}
        assert used == set(range(len(self.positions))), (self.name, "unused vertices")
        volume = sum(dot(self.positions[a], cross(self.positions[b], self.positions[c]))
                     for a, b, c in self.triangles) / 6.0
        assert volume > 0, (self.name, "inward-facing", volume)
        return volume

    def normals(self):
        """Area-weighted average of the face normals around each vertex."""
        acc = [(0.0, 0.0, 0.0)] * len(self.positions)
        for a, b, c in self.triangles:
            pa, pb, pc = self.positions[a], self.positions[b], self.positions[c]
            n = cross(sub(pb, pa), sub(pc, pa))
            for i in (a, b, c):
                acc[i] = (acc[i][0] + n[0], acc[i][1] + n[1], acc[i][2] + n[2])
        return [normalize(n) for n in acc]


def tube(name, rings, segments, bottom, top):
    """A closed tube around the Y axis. rings: (y, cx, cz, rx, rz, weights) with y increasing;
    ring vertex j sits at angle 2 pi j / segments from +X towards +Z. bottom, top: the pole
    vertices (position, weights) closing each end with a fan."""
    part = Part(name)
    first = []
    for y, cx, cz, rx, rz, w in rings:
        first.append(len(part.positions))
        for j in range(segments):
            a = 2.0 * math.pi * j / segments
            part.vertex((cx + rx * math.cos(a), y, cz + rz * math.sin(a)), w)
    low = part.vertex(*bottom)
    high = part.vertex(*top)
    for i in range(len(rings) - 1):
        for j in range(segments):
            k = (j + 1) % segments
            a, b = first[i] + j, first[i] + k
            c, d = first[i + 1] + k, first[i + 1] + j
            part.triangles += [(a, d, c), (a, c, b)]
    last = first[-1]
    for j in range(segments):
        k = (j + 1) % segments
        part.triangles.append((low, first[0] + j, first[0] + k))
        part.triangles.append((high, last + k, last + j))
    return part


def box(name, lo, hi, weights):
    """A closed box of 8 shared corners and 12 outward triangles."""
    part = Part(name)
    for i in range(8):
        part.vertex((hi[0] if i & 1 else lo[0], hi[1] if i & 2 else lo[1],
                     hi[2] if i & 4 else lo[2]), weights)
    quads = [(0, 4, 6, 2), (1, 3, 7, 5),  # -X, +X
             (0, 1, 5, 4), (2, 6, 7, 3),  # -Y, +Y
             (0, 2, 3, 1), (4, 5, 7, 6)]  # -Z, +Z
    for a, b, c, d in quads:
        part.triangles += [(a, b, c), (a, c, d)]
    return part


def joints_and_weights(w, joint_index):
    """Up to four (joint, weight) pairs, largest first, normalised so that the float32 weights
    sum to 1 (the largest weight takes the float32 rounding residue). Unused slots: joint 0,
    weight 0."""
    pairs = sorted(((v, joint_index[j]) for j, v in w.items() if v > 0.0),
                   key=lambda p: (-p[0], p[1]))[:4]
    assert pairs, "a vertex without weights"
    total = sum(v for v, _ in pairs)
    weights = [f32(v / total) for v, _ in pairs]
    weights[0] = f32(weights[0] + (1.0 - sum(weights)))
    assert abs(sum(weights) - 1.0) < 1e-7, weights
    joints = [j for _, j in pairs]
    assert len(set(joints)) == len(joints)
    pad = 4 - len(pairs)
    return tuple(joints + [0] * pad), tuple(weights + [0.0] * pad)


def skinned_primitive(buf, parts, joint_index, overrides=None):
    """Appends the parts as one indexed TRIANGLES primitive with POSITION, NORMAL, JOINTS_0 and
    WEIGHTS_0; overrides maps a vertex index to raw (joints, weights) written as they are."""
    positions, normals, joints, weights, indices = [], [], [], [], []
    for part in parts:
        part.check_closed()
        base = len(positions)
        positions += part.positions
        normals += part.normals()
        for w in part.weights:
            j, v = joints_and_weights(w, joint_index)
            joints.append(j)
            weights.append(v)
        indices += [i + base for t in part.triangles for i in t]
    for i, (j, v) in sorted((overrides or {}).items()):
        joints[i], weights[i] = j, v
    index_type = USHORT if len(positions) < 65536 else UINT
    attributes = {
        "POSITION": buf.floats(positions, "VEC3", bounds=True, target=ARRAY_BUFFER),
        "NORMAL": buf.floats(normals, "VEC3", target=ARRAY_BUFFER),
        "JOINTS_0": buf.accessor(joints, "VEC4", UBYTE, target=ARRAY_BUFFER),
        "WEIGHTS_0": buf.floats(weights, "VEC4", target=ARRAY_BUFFER),
    }
    return {"attributes": attributes,
            "indices": buf.accessor(indices, "SCALAR", index_type, target=ELEMENT_ARRAY_BUFFER),
            "mode": 4}


class Skeleton:
    """Joint nodes given by name, parent name and bind-pose local translation (no rotation)."""

    def __init__(self, joints, first_node):
        self.names = [j[0] for j in joints]
        self.parent = {j[0]: j[1] for j in joints}
        self.local = {j[0]: tuple(round(x, 6) + 0.0 for x in j[2]) for j in joints}
        self.node = {name: first_node + i for i, name in enumerate(self.names)}
        self.global_matrix = {}
        for name in self.names:  # parents come first
            m = translation_matrix(self.local[name])
            parent = self.parent[name]
            self.global_matrix[name] = m if parent is None else mat_mul(
                self.global_matrix[parent], m)

    def origin(self, name):
        m = self.global_matrix[name]
        return (m[12], m[13], m[14])

    def nodes(self):
        out = []
        for name in self.names:
            node = {"name": name}
            children = [self.node[c] for c in self.names if self.parent[c] == name]
            if children:
                node["children"] = children
            if any(self.local[name]):
                node["translation"] = list(self.local[name])
            out.append(node)
        return out

    def skin(self, buf, skin_order, name):
        """A skin whose joints are listed in skin_order (which need not be the node order)."""
        ibm = [affine_inverse(self.global_matrix[j]) for j in skin_order]
        roots = [j for j in skin_order if self.parent[j] is None]
        assert len(roots) == 1
        return {"name": name, "inverseBindMatrices": buf.floats(ibm, "MAT4"),
                "joints": [self.node[j] for j in skin_order], "skeleton": self.node[roots[0]]}


# ---------------------------------------------------------------------------------------------
# The walking figure.

FIGURE_JOINTS = [  # name, parent, bind-pose translation relative to the parent
    ("hips", None, (0.0, 0.95, 0.0)),
    ("spine", "hips", (0.0, 0.10, 0.0)),
    ("head", "spine", (0.0, 0.45, 0.0)),
    ("upper_arm_L", "spine", (0.24, 0.37, 0.0)),
    ("forearm_L", "upper_arm_L", (0.0, -0.28, 0.0)),
    ("upper_arm_R", "spine", (-0.24, 0.37, 0.0)),
    ("forearm_R", "upper_arm_R", (0.0, -0.28, 0.0)),
    ("thigh_L", "hips", (0.10, -0.03, 0.0)),
    ("shin_L", "thigh_L", (0.0, -0.44, 0.0)),
    ("foot_L", "shin_L", (0.0, -0.40, 0.0)),
    ("thigh_R", "hips", (-0.10, -0.03, 0.0)),
    ("shin_R", "thigh_R", (0.0, -0.44, 0.0)),
    ("foot_R", "shin_R", (0.0, -0.40, 0.0)),
]
# The skin lists the joints in another order than the nodes (legs before arms), so that a joint's
# index in the skin is not its node index minus one.
FIGURE_SKIN_ORDER = ["hips", "spine", "head", "thigh_L", "shin_L", "foot_L", "thigh_R",
                     "shin_R", "foot_R", "upper_arm_L", "forearm_L", "upper_arm_R", "forearm_R"]
THIGH, SHIN, FOOT_DROP = 0.44, 0.40, 0.08  # bone lengths; the sole is 8 cm below the ankle
FOOT_BACK, FOOT_FRONT = -0.06, 0.20         # heel and toe z relative to the ankle
HIP_DROP = 0.03                            # the thigh joints are 3 cm below the hips joint


def rounded_ends(rings, bottom_flat, top_flat):
    """Adds two shrinking rings and a pole at each end of a tube's rings (rounded ends);
    *_flat scales the end's height relative to its radius."""
    def end(ring, direction, flat):
        y, cx, cz, rx, rz, w = ring
        extra = []
        for deg in (35.0, 65.0):
            a = math.radians(deg)
            extra.append((y + direction * flat * max(rx, rz) * math.sin(a), cx, cz,
                          rx * math.cos(a), rz * math.cos(a), w))
        pole = ((cx, y + direction * flat * max(rx, rz), cz), w)
        return extra, pole
    low_rings, low_pole = end(rings[0], -1.0, bottom_flat)
    high_rings, high_pole = end(rings[-1], 1.0, top_flat)
    return low_rings[::-1] + rings + high_rings, low_pole, high_pole


def figure_parts(sk):
    parts = []
    # Torso: an elliptic tube from below the hips to the neck, hips blending into spine.
    profile = [(0.84, 0.150, 0.100), (0.95, 0.160, 0.105), (1.05, 0.140, 0.095),
               (1.20, 0.155, 0.100), (1.32, 0.165, 0.105), (1.40, 0.160, 0.100),
               (1.45, 0.110, 0.080), (1.48, 0.060, 0.055), (1.52, 0.055, 0.050)]
    rings = []
    for i in range(23):
        y = 0.84 + (1.52 - 0.84) * i / 22
        rx, rz = lerp_table(profile, y)
        s = clamp01((y - 0.98) / 0.14)
        rings.append((y, 0.0, 0.0, rx, rz, {"hips": 1.0 - s, "spine": s}))
    rings, low, high = rounded_ends(rings, 0.4, 0.8)
    parts.append(tube("torso", rings, 20, low, high))
    # Head: an ellipsoid whose top is at 1.8 m.
    c, r = (0.0, 1.67, 0.01), (0.095, 0.13, 0.11)
    rings = []
    for i in range(1, 12):
        lat = math.radians(-90.0 + 15.0 * i)
        rings.append((c[1] + r[1] * math.sin(lat), c[0], c[2], r[0] * math.cos(lat),
                      r[2] * math.cos(lat), {"head": 1.0}))
    parts.append(tube("head", rings, 20, ((c[0], c[1] - r[1], c[2]), {"head": 1.0}),
                      ((c[0], c[1] + r[1], c[2]), {"head": 1.0})))
    # Legs: hip to ankle, thigh blending into shin around the knee and shin into foot at the
    # ankle; a box foot whose sole is on y = 0.
    leg = [(0.07, 0.042, -0.005), (0.20, 0.048, -0.010), (0.34, 0.060, -0.015),
           (0.48, 0.055, 0.000), (0.62, 0.065, 0.000), (0.85, 0.078, 0.000), (0.96, 0.080, 0.0)]
    for side in ("L", "R"):
        x = sk.origin("thigh_" + side)[0]
        rings = []
        for i in range(26):
            y = 0.07 + (0.96 - 0.07) * i / 25
            radius, cz = lerp_table(leg, y)
            knee = clamp01((0.56 - y) / 0.16)  # 0 above 0.56 m, 1 below 0.40 m
            ankle = 0.5 * clamp01((0.14 - y) / 0.08)
            w = {"thigh_" + side: 1.0 - knee, "shin_" + side: knee * (1.0 - ankle),
                 "foot_" + side: ankle}
            rings.append((y, x, cz, radius, radius, w))
        rings, low, high = rounded_ends(rings, 1.0, 0.5)
        parts.append(tube("leg_" + side, rings, 16, low, high))
        ankle = sk.origin("foot_" + side)
        sole = round(ankle[1] - FOOT_DROP, 6) + 0.0  # 0: on the floor
        parts.append(box("foot_" + side, (x - 0.05, sole, FOOT_BACK),
                         (x + 0.05, sole + FOOT_DROP + 0.01, FOOT_FRONT),
                         {"foot_" + side: 1.0}))
    # Arms: shoulder to wrist, upper arm blending into forearm around the elbow; 2 cm or more
    # from the torso and the thighs at the bind pose.
    arm = [(0.87, 0.034), (1.00, 0.038), (1.14, 0.044), (1.30, 0.050), (1.46, 0.056)]
    for side in ("L", "R"):
        x = sk.origin("upper_arm_" + side)[0]
        rings = []
        for i in range(18):
            y = 0.87 + (1.46 - 0.87) * i / 17
            (radius,) = lerp_table(arm, y)
            elbow = clamp01((1.20 - y) / 0.12)
            rings.append((y, x, 0.0, radius, radius,
                          {"upper_arm_" + side: 1.0 - elbow, "forearm_" + side: elbow}))
        rings, low, high = rounded_ends(rings, 1.0, 0.6)
        parts.append(tube("arm_" + side, rings, 16, low, high))
    return parts


def gait(p):
    """The left leg at phase p in [0, 1): thigh swing forward, knee bend and foot pitch (toes
    down), in degrees. The thigh is 25 degrees forward at 0 and back at 0.5; the stance knee
    gives up to 15 degrees, the swing knee bends up to 60 degrees at 0.75; the heel rises up to
    15 degrees before toe-off (0.2 to 0.6), the toes staying on the floor."""
    swing = 25.0 * math.cos(2.0 * math.pi * p)
    if p < 0.5:
        knee = 15.0 * math.sin(2.0 * math.pi * p)
    else:
        knee = 60.0 * math.sin(2.0 * math.pi * (p - 0.5))
    pitch = 15.0 * math.sin(math.pi * (p - 0.2) / 0.4) ** 2 if 0.2 < p < 0.6 else 0.0
    return swing, max(0.0, knee), pitch


def leg_reach(p):
    """How far below its thigh joint the lowest point of the left foot is at phase p."""
    swing, knee, pitch = gait(p)
    a = math.radians(pitch)
    sole = max(FOOT_DROP * math.cos(a) + z * math.sin(a) for z in (FOOT_BACK, FOOT_FRONT))
    return (THIGH * math.cos(math.radians(swing)) + SHIN * math.cos(math.radians(swing - knee))
            + sole)


X_AXIS, Y_AXIS, Z_AXIS = (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)


def walk_pose(p):
    """Local TRS values of the animated joints at phase p of the walk. Forward (+Z) swings are
    negative turns about X. The hips sit as high as the lower foot allows, so that foot touches
    y = 0 (the leading foot from 1/24 s after its strike at 0 or 0.5, the trailing foot before):
    the hips bob by 5.7 cm (0.887 to 0.944 m), twice a cycle. The feet are level (their only
    turn is the hips' yaw) but for the heel raise before toe-off."""
    pose = {}
    reach = max(leg_reach(p), leg_reach((p + 0.5) % 1.0))
    pose[("hips", "translation")] = (0.0, HIP_DROP + reach, 0.0)
    pose[("hips", "rotation")] = quat_axis_angle(Y_AXIS, -4.0 * math.cos(2.0 * math.pi * p))
    pose[("spine", "rotation")] = quat_axis_angle(Y_AXIS, 8.0 * math.cos(2.0 * math.pi * p))
    for side, phase in (("L", p), ("R", (p + 0.5) % 1.0)):
        swing, knee, pitch = gait(phase)
        pose[("thigh_" + side, "rotation")] = quat_axis_angle(X_AXIS, -swing)
        pose[("shin_" + side, "rotation")] = quat_axis_angle(X_AXIS, knee)
        pose[("foot_" + side, "rotation")] = quat_axis_angle(X_AXIS, swing - knee + pitch)
        arm = -20.0 * math.cos(2.0 * math.pi * phase)  # opposite to the leg of its side
        pose[("upper_arm_" + side, "rotation")] = quat_axis_angle(X_AXIS, -arm)
        pose[("forearm_" + side, "rotation")] = quat_axis_angle(X_AXIS, -(15.0 + 0.5 * arm))
    return pose


def idle_pose(t):
    """Breathing: the spine leans back by up to 1.5 degrees and the chest widens (x) by 2% and
    deepens (z) by 3%, once every 2 s."""
    b = 0.5 - 0.5 * math.cos(2.0 * math.pi * t / 2.0)
    return {("spine", "rotation"): quat_axis_angle(X_AXIS, -1.5 * b),
            ("spine", "scale"): (1.0 + 0.02 * b, 1.0, 1.0 + 0.03 * b)}


def sampled_animation(buf, sk, name, pose_at, times):
    poses = [pose_at(t) for t in times]
    input_ = buf.times(times)
    samplers, channels = [], []
    for key in poses[0]:
        joint, path = key
        values = [pose[key] for pose in poses]
        if path == "rotation":  # keep neighbouring keys in one hemisphere for slerp
            for i in range(1, len(values)):
                if sum(a * b for a, b in zip(values[i - 1], values[i])) < 0:
                    values[i] = tuple(-v for v in values[i])
        kind = "VEC4" if path == "rotation" else "VEC3"
        samplers.append({"input": input_, "interpolation": "LINEAR",
                         "output": buf.floats(values, kind)})
        channels.append({"sampler": len(samplers) - 1,
                         "target": {"node": sk.node[joint], "path": path}})
    return {"name": name, "channels": channels, "samplers": samplers}


def walking_figure():
    buf = Buffer()
    sk = Skeleton(FIGURE_JOINTS, first_node=1)
    joint_index = {name: i for i, name in enumerate(FIGURE_SKIN_ORDER)}
    primitive = skinned_primitive(buf, figure_parts(sk), joint_index)
    mesh = {"name": "figure_mesh", "primitives": [primitive]}
    skin = sk.skin(buf, FIGURE_SKIN_ORDER, "figure_skin")
    walk_times = [i / 24.0 for i in range(25)]
    # the last key is the first again: a pose of phase i % 24, at time 1.0
    walk = sampled_animation(buf, sk, "walk", lambda t: walk_pose((round(t * 24) % 24) / 24.0),
                             walk_times)
    idle_times = [i / 24.0 for i in range(49)]
    idle = sampled_animation(buf, sk, "idle", lambda t: idle_pose((round(t * 24) % 48) / 24.0),
                             idle_times)
    nodes = [{"name": "figure", "mesh": 0, "skin": 0}] + sk.nodes()
    doc = document(buf, scene=0, scenes=[{"name": "figure", "nodes": [0, sk.node["hips"]]}],
                   nodes=nodes, meshes=[mesh], skins=[skin], animations=[walk, idle])
    return doc, buf.data


# ---------------------------------------------------------------------------------------------
# The test files.

BAR_JOINTS = [("root", None, (0.0, 0.0, 0.0)), ("tip", "root", (1.0, 0.0, 0.0))]
BAR_RINGS, BAR_HALF = 9, 0.1  # rings at x = 0, 0.25, ..., 2; a 0.2 m square section
# bad_weights.gltf: vertex 16 (the first corner of the ring at x = 1) has weights 0 0 0 0 and
# vertex 20 (the first corner of the ring at x = 1.25) has weights NaN 0.75 0 0.
BAD_ZERO_VERTEX, BAD_NAN_VERTEX = 16, 20


def bar_part():
    """A closed square bar along +X, rings of 4 corners, the tip's weight rising linearly from 0
    at x = 0.5 to 1 at x = 1.5; each end closed by two triangles."""
    part = Part("bar")
    h = BAR_HALF
    for i in range(BAR_RINGS):
        x = 2.0 * i / (BAR_RINGS - 1)
        tip = clamp01(x - 0.5)
        for y, z in ((-h, -h), (h, -h), (h, h), (-h, h)):
            part.vertex((x, y, z), {"root": 1.0 - tip, "tip": tip})
    for i in range(BAR_RINGS - 1):
        for j in range(4):
            a, b = 4 * i + j, 4 * i + (j + 1) % 4
            c, d = b + 4, a + 4
            part.triangles += [(a, b, c), (a, c, d)]
    last = 4 * (BAR_RINGS - 1)
    part.triangles += [(0, 3, 2), (0, 2, 1), (last, last + 1, last + 2), (last, last + 2, last + 3)]
    return part


def z_turn(degrees):
    return quat_axis_angle(Z_AXIS, degrees)


def z_turn_rate(degrees, per_second):
    """d/dt of z_turn(angle) while the angle changes at per_second degrees a second."""
    h = math.radians(degrees) / 2.0
    rate = math.radians(per_second) / 2.0
    return (0.0, 0.0, math.cos(h) * rate + 0.0, -math.sin(h) * rate + 0.0)


# "cubic": (time, in-tangent, value, out-tangent), tangents in units per second. glTF's cubic
# Hermite spline (normalised) turns the tip by 36.44, 60.23 and 77.11 degrees at t = 0.25, 0.5
# and 0.75 s (and 1.5 s: 60.23), where "linear" turns it by 22.5, 45 and 67.5 degrees.
CUBIC_KEYS = [
    (0.0, z_turn_rate(0.0, 180.0), z_turn(0.0), z_turn_rate(0.0, 180.0)),
    (1.0, z_turn_rate(90.0, 45.0), z_turn(90.0), z_turn_rate(90.0, -45.0)),
    (2.0, z_turn_rate(0.0, -180.0), z_turn(0.0), z_turn_rate(0.0, -180.0)),
]


def bending_bar(bad=False):
    buf = Buffer()
    sk = Skeleton(BAR_JOINTS, first_node=1)
    joint_index = {"root": 0, "tip": 1}
    overrides = None
    if bad:
        overrides = {BAD_ZERO_VERTEX: ((0, 1, 0, 0), (0.0, 0.0, 0.0, 0.0)),
                     BAD_NAN_VERTEX: ((0, 1, 0, 0), (float("nan"), 0.75, 0.0, 0.0))}
    primitive = skinned_primitive(buf, [bar_part()], joint_index, overrides)
    mesh = {"name": "bar_mesh", "primitives": [primitive]}
    skin = sk.skin(buf, ["root", "tip"], "bar_skin")
    tip, root = sk.node["tip"], sk.node["root"]

    def anim(name, interpolation, times, channels):
        input_ = buf.times(times)
        samplers, out = [], []
        for node, path, kind, values in channels:
            samplers.append({"input": input_, "interpolation": interpolation,
                             "output": buf.floats(values, kind)})
            out.append({"sampler": len(samplers) - 1, "target": {"node": node, "path": path}})
        return {"name": name, "channels": out, "samplers": samplers}

    cubic_values = [v for _, tin, value, tout in CUBIC_KEYS for v in (tin, value, tout)]
    animations = [
        anim("linear", "LINEAR", [0.0, 1.0, 2.0],
             [(tip, "rotation", "VEC4", [z_turn(0.0), z_turn(90.0), z_turn(0.0)]),
              (root, "translation", "VEC3", [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 0.0, 0.0)])]),
        anim("step", "STEP", [0.0, 1.0, 2.0],
             [(tip, "rotation", "VEC4", [z_turn(0.0), z_turn(90.0), z_turn(0.0)])]),
        anim("cubic", "CUBICSPLINE", [k[0] for k in CUBIC_KEYS],
             [(tip, "rotation", "VEC4", cubic_values)]),
    ]
    nodes = [{"name": "bar", "mesh": 0, "skin": 0}] + sk.nodes()
    doc = document(buf, scene=0, scenes=[{"name": "bar", "nodes": [0, root]}], nodes=nodes,
                   meshes=[mesh], skins=[skin], animations=animations)
    return doc, buf.data


def morph_cube():
    """A unit cube of 8 shared corners; target 0 lifts the +Y face by 0.5, target 1 pushes the
    +X face by 0.25 in x; "inflate" turns target 0 on over the first second, then target 1."""
    buf = Buffer()
    part = box("cube", (-0.5, -0.5, -0.5), (0.5, 0.5, 0.5), {})
    part.check_closed()
    lift = [(0.0, 0.5 if p[1] > 0 else 0.0, 0.0) for p in part.positions]
    push = [(0.25 if p[0] > 0 else 0.0, 0.0, 0.0) for p in part.positions]
    primitive = {
        "attributes": {
            "POSITION": buf.floats(part.positions, "VEC3", bounds=True, target=ARRAY_BUFFER),
            "NORMAL": buf.floats(part.normals(), "VEC3", target=ARRAY_BUFFER),
        },
        "indices": buf.accessor([i for t in part.triangles for i in t], "SCALAR", USHORT,
                                target=ELEMENT_ARRAY_BUFFER),
        "mode": 4,
        "targets": [{"POSITION": buf.floats(lift, "VEC3", bounds=True, target=ARRAY_BUFFER)},
                    {"POSITION": buf.floats(push, "VEC3", bounds=True, target=ARRAY_BUFFER)}],
    }
    mesh = {"name": "cube_mesh", "primitives": [primitive], "weights": [0.0, 0.0],
            "extras": {"targetNames": ["lift_top", "push_right"]}}
    input_ = buf.times([0.0, 1.0, 2.0])
    output = buf.floats([0.0, 0.0, 1.0, 0.0, 1.0, 1.0], "SCALAR")
    animation = {"name": "inflate",
                 "channels": [{"sampler": 0, "target": {"node": 0, "path": "weights"}}],
                 "samplers": [{"input": input_, "interpolation": "LINEAR", "output": output}]}
    doc = document(buf, scene=0, scenes=[{"name": "cube", "nodes": [0]}],
                   nodes=[{"name": "cube", "mesh": 0}], meshes=[mesh], animations=[animation])
    return doc, buf.data


# ---------------------------------------------------------------------------------------------


def write(path, data):
    path.write_bytes(data)
    print("wrote %s (%d bytes)" % (path, len(data)))


def main():
    parser = argparse.ArgumentParser(description="Writes the skinned / morphed glTF models.")
    parser.add_argument("--out-dir", required=True, type=Path, help="folder to write into")
    only = parser.add_mutually_exclusive_group()
    only.add_argument("--figure-only", action="store_true", help="only walking_figure.gltf")
    only.add_argument("--tests-only", action="store_true", help="only the small test files")
    args = parser.parse_args()
    out = args.out_dir
    out.mkdir(parents=True, exist_ok=True)
    if not args.tests_only:
        doc, data = walking_figure()
        write(out / "walking_figure.gltf", gltf_embedded(doc, data))
    if not args.figure_only:
        doc, data = bending_bar()
        write(out / "bending_bar.gltf", gltf_embedded(doc, data))
        write(out / "bending_bar_external.gltf", gltf_external(doc, "bending_bar_external.bin"))
        write(out / "bending_bar_external.bin", bytes(data))
        write(out / "bending_bar.glb", glb(doc, data))
        doc, data = morph_cube()
        write(out / "morph_cube.gltf", gltf_embedded(doc, data))
        doc, data = bending_bar(bad=True)
        write(out / "bad_weights.gltf", gltf_embedded(doc, data))


if __name__ == "__main__":
    main()
