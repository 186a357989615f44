#!/usr/bin/env python3
"""Layouts of the blind set v27, each unlike every earlier one:
- blind-hairpin: a two-way mountain road climbing through a hairpin bend (the road turns back on
  itself 70 m ahead, 20 m across), a viewpoint lay-by on the outside of the bend with a coach in
  it, traffic coming down, a cyclist climbing ahead of the ego.
- blind-dropoff: an airport terminal's one-way forecourt: a kerbside drop-off lane with taxis
  queueing and cars stopping, two through lanes, a bus lane on the far side, a zebra crossing.
Run by make_layouts.py, or alone: python3 tests/data/layouts/layouts_v27.py (deterministic).
"""
import math

from layout_lib import SIZES, lane, line, obj, static, track_along, write

COACH = [12.5, 2.55, 3.5]


def hairpin_path(offset):
    """The climbing road's lane at `offset` (left positive): east along y=offset to x=70, a
    half circle to the left about (70, 10) (radius 10 - offset), then west along y=20-offset."""
    r = 10 - offset
    pts = line(-60, offset, 70, offset)
    for k in range(1, 13):
        a = -math.pi / 2 + math.pi * k / 12
        pts.append([70 + r * math.cos(a), 10 + r * math.sin(a), 0.0])
    return pts + line(70, 20 - offset, -60, 20 - offset)[1:]


def hairpin():
    """Up lane (the ego's) at offset 0, down lane at offset 3.5 drawn against it (backward); a lay-by
    on the outside of the bend along the ego's approach (y=-4.5, x=45 to 75)."""
    up = hairpin_path(0.0)
    down = hairpin_path(3.5)
    down_travel = list(reversed(down))
    lanes = [lane("up", up, 3.5), dict(lane("down", down, 3.5), direction="backward"),
             lane("viewpoint_lay_by", line(45, -4.5, 75, -4.5), 4.0, "parking")]
    length = sum(math.dist(a[:2], b[:2]) for a, b in zip(down_travel, down_travel[1:]))
    objects = [obj(1, "vehicle.bicycle", track_along(up, 60 + 14, 4.5), "blue"),
               obj(2, "vehicle.bus.rigid", static(62, -4.5), "white", COACH),
               obj(3, "vehicle.car", track_along(down_travel, length - 260, 8), "red"),
               obj(4, "vehicle.car", track_along(down_travel, length - 230, 8), "silver", SIZES["suv"]),
               obj(5, "vehicle.truck", track_along(down_travel, length - 120, 6), "yellow"),
               obj(6, "vehicle.car", static(49, -4.5), "black"),
               obj(7, "vehicle.motorcycle", track_along(up, 60 - 12, 5), "black"),
               obj(8, "human.pedestrian.adult", track_along(line(58, -7, 66, -7), 0, 0.8))]
    write("blind-hairpin", "hand-made layout: a two-way mountain road climbing through a hairpin bend, a viewpoint "
          "lay-by with a coach, traffic coming down, a cyclist climbing ahead", lanes, up, 5.0, objects)


def dropoff():
    """One-way eastbound: drop-off lane at the kerb on the right (y=-3.5, a 'parking' lane: cars
    stop there), through lanes y=0 and y=3.5, a bus lane y=7; a zebra crossing at x=60."""
    kerb, through_r, through_l, bus = (line(-60, y, 220, y) for y in (-3.5, 0, 3.5, 7.0))
    lanes = [lane("dropoff_kerb", kerb, 3.0, "parking"), lane("through_right", through_r),
             lane("through_left", through_l), lane("bus_lane", bus)]
    van = [5.2, 2.0, 2.1]
    objects = [obj(1, "vehicle.car", static(20, -3.5), "yellow"), obj(2, "vehicle.car", static(26, -3.5), "yellow"),
               obj(3, "vehicle.car", static(32, -3.5), "yellow"), obj(4, "vehicle.car", static(45, -3.5), "white", van),
               obj(5, "vehicle.car", static(80, -3.5), "black", SIZES["suv"]),
               obj(6, "vehicle.car", track_along(through_l, 60 + 25, 6), "grey"),
               obj(7, "vehicle.car", track_along(through_r, 60 + 18, 4), "blue"),
               obj(8, "vehicle.bus.rigid", track_along(bus, 60 + 40, 5), "green"),
               obj(9, "vehicle.car", track_along(through_l, 60 - 14, 6), "red"),
               obj(10, "human.pedestrian.adult", track_along(line(60, -6, 60, 10), 0, 1.3)),
               obj(11, "vehicle.car", static(95, -3.5), "yellow")]
    write("blind-dropoff", "hand-made layout: an airport terminal's one-way forecourt, taxis queueing in a kerbside "
          "drop-off lane, two through lanes, a bus lane", lanes, through_r, 4.0, objects)


def main():
    hairpin()
    dropoff()


if __name__ == "__main__":
    main()
