"""Shared helpers of the layout generators (make_layouts.py, more_layouts.py): polylines, lanes,
cameras, tracks and the scene writer. Deterministic, no randomness."""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
FRAMES, HZ = 100, 10.0


def line(x0, y0, x1, y1, step=5.0):
    n = max(1, round(math.hypot(x1 - x0, y1 - y0) / step))
    return [[x0 + (x1 - x0) * k / n, y0 + (y1 - y0) * k / n, 0.0] for k in range(n + 1)]


def joined(*points):
    """A polyline through the given corners, 5 m steps on each leg."""
    out = []
    for a, b in zip(points, points[1:]):
        out += line(a[0], a[1], b[0], b[1])[:-1]
    return out + [[points[-1][0], points[-1][1], 0.0]]


def lane(lid, pts, width=3.5, kind="driving"):
    return {"id": lid, "type": kind, "width": width, "direction": "forward",
            "centerline": [[round(v, 3) for v in p] for p in pts]}


def camera(name, yaw_deg):
    c, s = math.cos(math.radians(yaw_deg)), math.sin(math.radians(yaw_deg))
    # OpenCV axes (right, down, forward) in the ego's FLU frame, turned by yaw.
    r = [[s, 0, c], [-c, 0, s], [0, -1, 0]]
    m = [r[0] + [1.5], r[1] + [0.0], r[2] + [1.6], [0, 0, 0, 1]]
    return {"name": name, "width": 1920, "height": 1280, "fx": 2000.0, "fy": 2000.0, "cx": 960.0, "cy": 640.0,
            "distortion": {"model": "none"}, "sensor_to_ego": [round(v, 12) for row in m for v in row]}


def pose(x, y, yaw, z=0):
    c, s = math.cos(yaw), math.sin(yaw)
    return [c, -s, 0, x, s, c, 0, y, 0, 0, 1, z, 0, 0, 0, 1]


def sample(pts, dist):
    """Point and yaw at arc length dist along a polyline (extrapolated at both ends)."""
    acc = 0.0
    for a, b in zip(pts, pts[1:]):
        seg = math.hypot(b[0] - a[0], b[1] - a[1])
        if dist <= acc + seg or b is pts[-1]:
            t = (dist - acc) / seg
            return a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, math.atan2(b[1] - a[1], b[0] - a[0])
        acc += seg
    raise ValueError("empty polyline")


def track_along(pts, s0, speed, reverse_yaw=False):
    out = []
    for f in range(FRAMES):
        x, y, yaw = sample(pts, s0 + speed * f / HZ)
        out.append({"frame": f, "center": [round(x, 3), round(y, 3), 0.8], "yaw": round(yaw + (math.pi if reverse_yaw else 0), 4)})
    return out


def static(x, y, yaw=0.0):
    return [{"frame": f, "center": [x, y, 0.8], "yaw": yaw} for f in range(FRAMES)]


SIZES = {"vehicle.car": [4.6, 1.9, 1.5], "suv": [4.9, 2.0, 1.8], "vehicle.truck": [7.5, 2.5, 3.2],
         "vehicle.bus.rigid": [12.0, 2.55, 3.2], "vehicle.motorcycle": [2.1, 0.8, 1.4],
         "vehicle.bicycle": [1.8, 0.6, 1.5], "human.pedestrian.adult": [0.6, 0.6, 1.75],
         "movable_object.trafficcone": [0.4, 0.4, 0.7], "vehicle.emergency.police": [4.9, 1.95, 1.6]}
COLORS = {"red": [200, 30, 30], "white": [235, 235, 235], "black": [20, 20, 22], "silver": [180, 180, 186],
          "grey": [120, 120, 125], "blue": [30, 60, 200], "green": [30, 140, 50], "yellow": [240, 200, 25],
          "orange": [240, 120, 20]}


def obj(n, category, track, color=None, size=None):
    o = {"id": f"obj_{n}", "category": category, "size_lwh": size or SIZES[category], "track": track}
    if color:
        o["color_rgb"] = COLORS[color]
    return o


class Placement:
    """Where a layout drawn in its own frame (ego starting at the origin, heading +x) stands in the
    world: turned by yaw_deg about the origin, then moved by (tx, ty); ground(x, y) gives the road's
    height at a local point (a hill). The default leaves the layout as drawn."""

    def __init__(self, yaw_deg=0.0, tx=0.0, ty=0.0, ground=None):
        self.yaw, self.tx, self.ty = math.radians(yaw_deg), tx, ty
        self.ground = ground or (lambda x, y: 0.0)

    def point(self, x, y, z_above=0.0):
        c, s = math.cos(self.yaw), math.sin(self.yaw)
        return [round(c * x - s * y + self.tx, 3), round(s * x + c * y + self.ty, 3),
                round(self.ground(x, y) + z_above, 3)]

    def lanes(self, lanes):
        return [dict(ln, centerline=[self.point(p[0], p[1]) for p in ln["centerline"]]) for ln in lanes]

    def objects(self, objects):
        out = []
        for o in objects:
            track = [dict(t, center=self.point(t["center"][0], t["center"][1], t["center"][2]),
                          yaw=round(t["yaw"] + self.yaw, 4)) for t in o["track"]]
            out.append(dict(o, track=track))
        return out


def write(name, source, lanes, ego_pts, ego_speed, objects, placement=None):
    d = os.path.join(HERE, name)
    os.makedirs(d, exist_ok=True)
    frames = []
    if placement:
        lanes, objects = placement.lanes(lanes), placement.objects(objects)
    for f in range(FRAMES):
        x, y, yaw = sample(ego_pts, ego_speed * f / HZ - sample_origin(ego_pts))
        if placement:
            x, y, z = placement.point(x, y)
            world = pose(round(x, 4), round(y, 4), round(yaw + placement.yaw, 6), z)
        else:
            world = pose(round(x, 4), round(y, 4), round(yaw, 6))
        frames.append({"index": f, "timestamp_s": round(f / HZ, 3), "ego_to_world": world, "images": {}})
    scene = {"format": "chatsim-scene/1", "name": name, "source": source, "layout_only": True, "frame_rate_hz": HZ,
             "ego_origin": "rear_axle", "cameras": [camera("front", 0), camera("front_left", 45), camera("front_right", -45)],
             "frames": frames}
    for fname, data in (("scene.json", scene), ("lanes.json", {"lanes": lanes}), ("objects.json", {"objects": objects})):
        with open(os.path.join(d, fname), "w") as f:
            json.dump(data, f, indent=1)
            f.write("\n")


def sample_origin(pts):
    """Arc length of the polyline's first point before x = 0 (the ego starts at the origin)."""
    return pts[0][0]


def frange(a, b, step):
    out, x = [], a
    while x < b - 1e-9:
        out.append(x)
        x += step
    return out + [b]


def offset(pts, d):
    """The polyline moved d metres to its left."""
    out = []
    for k, p in enumerate(pts):
        a, b = pts[max(k - 1, 0)], pts[min(k + 1, len(pts) - 1)]
        yaw = math.atan2(b[1] - a[1], b[0] - a[0])
        out.append([p[0] - d * math.sin(yaw), p[1] + d * math.cos(yaw), 0.0])
    return out
