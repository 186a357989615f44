#!/usr/bin/env python3
"""Layouts of the blind set v25, each unlike every earlier one:
- blind-angled: a high street with 45-degree angled parking on both sides (bays drawn as short
  lanes at an angle to the road, cars nose-in), a van double-parked in the ego's lane with its
  hazards on, a car backing out of an angled bay, a mid-block crossing.
- blind-merge: the ego itself merges: it drives up an on-ramp that curves onto a three-lane
  motorway and joins its kerb lane within the clip; motorway traffic in all three lanes, a truck in
  the kerb lane the ego merges behind, a car on the hard shoulder.
Run by make_layouts.py, or alone: python3 tests/data/layouts/layouts_v25.py (deterministic).
"""
import math

from layout_lib import FRAMES, HZ, SIZES, lane, line, obj, static, track_along, write

VAN = [5.2, 2.0, 2.1]
BAY = math.radians(45)


def angled_bay(x, side):
    """A 45-degree bay whose mouth is at (x, +-4.6) on the kerb side, 5 m long, entered forwards
    (nose-in toward the kerb, pointing along +x and away from the road)."""
    sgn = 1 if side == "left" else -1
    x0, y0 = x, sgn * 4.6
    return line(x0, y0, x0 + 5 * math.cos(BAY), y0 + sgn * 5 * math.sin(BAY), 1.0)


def bay_centre(x, side):
    sgn = 1 if side == "left" else -1
    return x + 2.5 * math.cos(BAY), sgn * (4.6 + 2.5 * math.sin(BAY)), sgn * BAY


def backing_out(x, side, start_frame, speed):
    """A car nose-in in an angled bay, reversing out of it from start_frame (1.5 m at most)."""
    cx, _, yaw = bay_centre(x, side)
    cy = -4.4 if side == "right" else 7.7  # on the parking lane's centreline, as the parked ones
    out = []
    for f in range(FRAMES):
        back = min(1.5, max(0.0, (f - start_frame) / HZ * speed))
        out.append({"frame": f, "center": [round(cx - back * math.cos(yaw), 3), round(cy - back * math.sin(yaw), 3), 0.8],
                    "yaw": round(yaw, 4)})
    return out


def angled():
    """Eastbound y=0 (the ego's, 3.3 wide, at 4 m/s), westbound y=3.3; angled bays on both sides
    from x=-40 to 120, drawn as one 4.5 m parking lane per side (y=-4.4, y=7.7) with the cars at 45
    degrees in it, nose-in toward the kerb."""
    east, west = line(-60, 0, 200, 0), line(200, 3.3, -60, 3.3)
    lanes = [lane("east", east, 3.3), lane("west", west, 3.3),
             lane("bays_right", line(-40, -4.4, 120, -4.4), 4.5, "parking"),
             lane("bays_left", line(120, 7.7, -40, 7.7), 4.5, "parking")]
    car = SIZES["vehicle.car"]

    def parked(n, x, side, color, size=None):
        cx, _, yaw = bay_centre(x, side)
        cy = -4.4 if side == "right" else 7.7  # the bays' cars stand on the parking lanes' centrelines
        return obj(n, "vehicle.car", static(round(cx, 3), cy, yaw), color, size or car)

    objects = [parked(1, 10, "right", "red"), parked(2, 13.5, "right", "white"), parked(3, 24, "right", "black"),
               parked(4, 31, "right", "blue", SIZES["suv"]), parked(5, 45, "right", "silver"),
               parked(6, 6, "left", "green"), parked(7, 20, "left", "yellow"), parked(8, 27, "left", "grey", VAN),
               obj(9, "vehicle.car", static(55, 0.0), "white", VAN),
               obj(10, "vehicle.car", backing_out(62, "right", 40, 0.8), "orange"),
               obj(11, "vehicle.car", track_along(west, 200 - 70, 6), "black"),
               obj(12, "vehicle.motorcycle", track_along(west, 200 - 120, 7), "red"),
               obj(13, "human.pedestrian.adult", track_along(line(38, -6, 38, 9), 0, 1.2)),
               obj(14, "vehicle.car", track_along(west, 200 - 150, 7), "silver"),
               obj(15, "vehicle.truck", static(80, 7.7, math.pi), "white")]
    write("blind-angled", "hand-made layout: a high street with 45-degree angled parking both sides, a van "
          "double-parked in the ego's lane, a car backing out of a bay", lanes, east, 4.0, objects)


def ramp_path():
    """The on-ramp: from (-60, -20) rising along a gentle left curve to join the kerb lane (y=0) at
    x=40, then the kerb lane."""
    pts = []
    for k in range(21):
        x = -60 + 100 * k / 20
        y = -20 + 20 * (1 - math.cos(math.pi * k / 20)) / 2
        pts.append([x, y, 0.0])
    return pts + line(40, 0, 300, 0)[1:]


def merge():
    """Motorway eastbound: kerb y=0, middle 3.6, fast 7.2 (3.6 wide); westbound 13.2, 16.8, 20.4
    behind a barrier; a hard shoulder y=-3.3 from x=60; the ramp lane from (-60,-20) joining the
    kerb lane at x=40 (ending there). The ego drives up the ramp at 20 m/s."""
    east = {y: line(-60, y, 300, y) for y in (0.0, 3.6, 7.2)}
    west = {y: line(300, y, -60, y) for y in (13.2, 16.8, 20.4)}
    ramp = ramp_path()
    lanes = [lane("kerb", east[0.0], 3.6), lane("middle", east[3.6], 3.6), lane("fast", east[7.2], 3.6),
             lane("west_fast", west[13.2], 3.6), lane("west_middle", west[16.8], 3.6), lane("west_kerb", west[20.4], 3.6),
             lane("on_ramp", ramp[:21], 3.6), lane("hard_shoulder", line(60, -3.3, 300, -3.3), 3.0, "shoulder")]
    objects = [obj(1, "vehicle.truck", track_along(east[0.0], 60 + 10, 20), "blue"),
               obj(2, "vehicle.car", track_along(east[3.6], 60 + 20, 24), "white"),
               obj(3, "vehicle.car", track_along(east[7.2], 60 - 30, 32), "red"),
               obj(4, "vehicle.car", track_along(east[0.0], 60 - 45, 20), "silver"),
               obj(5, "vehicle.car", track_along(east[3.6], 60 - 10, 23), "black", SIZES["suv"]),
               obj(6, "vehicle.bus.rigid", track_along(west[20.4], 360 - 200, 20), "white"),
               obj(7, "vehicle.car", track_along(west[13.2], 360 - 250, 30), "yellow"),
               obj(8, "vehicle.car", static(140, -3.3), "grey"),
               obj(9, "vehicle.truck", track_along(east[0.0], 60 + 120, 17), "green"),
               obj(10, "vehicle.motorcycle", track_along(east[7.2], 60 + 40, 30), "black")]
    write("blind-merge", "hand-made layout: the ego merging from an on-ramp onto a three-lane motorway behind a "
          "truck, a car on the hard shoulder", lanes, ramp, 20.0, objects)


def main():
    angled()
    merge()


if __name__ == "__main__":
    main()
