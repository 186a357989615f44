#!/usr/bin/env python3
"""Layouts of the blind set v26, each unlike every earlier one:
- blind-rightturn: the ego turns right within the clip, from a two-way road into the cross street
  of a crossroads 35 m ahead (right-hand traffic); cars wait on the cross street, a car is parked
  in the street the ego turns into, a parking lane before the junction on the main road.
- blind-school: a slow residential street by a school: the ego follows a cyclist in its lane,
  parking alternates sides, a school bus stands at the school on the left, children cross, a car
  backs out of a driveway on the right, a side street to the left.
Run by make_layouts.py, or alone: python3 tests/data/layouts/layouts_v26.py (deterministic).
"""
import math

from layout_lib import FRAMES, HZ, SIZES, lane, line, obj, static, track_along, write

VAN = [5.2, 2.0, 2.1]


def right_turn_path():
    """East along y=0 to x=33, a quarter circle right (radius 5.25) into the southbound lane
    x=38.25, then south."""
    pts = line(-60, 0, 33, 0)
    for k in range(1, 7):
        a = math.pi / 2 * k / 6
        pts.append([33 + 5.25 * math.sin(a), -5.25 + 5.25 * math.cos(a), 0.0])
    return pts + line(38.25, -5.25, 38.25, -200)[1:]


def rightturn():
    """Main road: eastbound y=0, westbound y=3.5 (3.5 wide), a parking lane on the right (y=-3)
    from x=-60 to 28; cross street at x=40: southbound x=38.25, northbound x=41.75, a parking
    lane on its west side (x=35.25) from y=-15 to -150. The ego turns right into the southbound
    lane at 6 m/s."""
    east, west = line(-60, 0, 220, 0), line(220, 3.5, -60, 3.5)
    south, north = line(38.25, 150, 38.25, -200), line(41.75, -200, 41.75, 150)
    lanes = [lane("main_east", east), lane("main_west", west), lane("south", south), lane("north", north),
             lane("turn_east_south", right_turn_path()[18:26]),
             lane("main_parking", line(-60, -3.0, 28, -3.0), 2.5, "parking"),
             lane("cross_parking", line(35.25, -15, 35.25, -150), 2.5, "parking")]
    objects = [obj(1, "vehicle.car", track_along(east, 60 + 20, 6), "white"),
               obj(2, "vehicle.car", static(41.75, -12, math.pi / 2), "black", SIZES["suv"]),
               obj(3, "vehicle.car", static(41.75, -19.5, math.pi / 2), "red"),
               obj(4, "vehicle.bus.rigid", track_along(west, 100, 7), "white"),
               obj(5, "vehicle.car", static(35.25, -40, -math.pi / 2), "silver"),
               obj(6, "vehicle.car", static(35.25, -55, -math.pi / 2), "yellow"),
               obj(7, "human.pedestrian.adult", track_along(line(33, -10, 46, -10), 0, 1.2)),
               obj(8, "vehicle.bicycle", track_along(north, 120, 4), "black"),
               obj(9, "vehicle.motorcycle", track_along(west, 150, 9), "red"),
               obj(10, "vehicle.car", static(15, -3.0), "green", VAN),
               obj(11, "vehicle.truck", track_along(east, 60 - 15, 6), "blue"),
               obj(12, "vehicle.car", track_along(south, 150 + 25, 5), "blue")]
    write("blind-rightturn", "hand-made layout: the ego turning right at a crossroads into a cross street, cars "
          "waiting on it, a car parked in the street it turns into", lanes, right_turn_path(), 6.0, objects)


def backing_out_of_driveway(x, start_frame, speed):
    """A car nose-in in a driveway on the right (pointing south, away from the road), reversing
    north toward the road from start_frame, 4 m at most."""
    out = []
    for f in range(FRAMES):
        back = min(4.0, max(0.0, (f - start_frame) / HZ * speed))
        out.append({"frame": f, "center": [x, round(-8.5 + back, 3), 0.8], "yaw": round(-math.pi / 2, 4)})
    return out


def school():
    """Eastbound y=0, westbound y=3.2 (3.2 wide), parking on the right (y=-2.6) for x<40 and
    x>120, on the left (y=5.8) for 50<x<110; a school on the left from x=60 to 100 with its bus
    stopped at x=80; a side street to the left at x=120. The ego drives at 4 m/s behind a
    cyclist."""
    east, west = line(-60, 0, 220, 0), line(220, 3.2, -60, 3.2)
    lanes = [lane("east", east, 3.2), lane("west", west, 3.2),
             lane("park_right_a", line(-60, -2.6, 40, -2.6), 2.0, "parking"),
             lane("park_right_b", line(125, -2.6, 220, -2.6), 2.0, "parking"),
             lane("park_left", line(110, 5.8, 50, 5.8), 2.0, "parking"),
             lane("elm_north", line(121.6, 4.8, 121.6, 90)), lane("elm_south", line(118.4, 90, 118.4, 4.8))]
    bus = [12.0, 2.55, 3.2]
    objects = [obj(1, "vehicle.bicycle", track_along(east, 60 + 12, 4), "black"),
               obj(2, "vehicle.car", backing_out_of_driveway(60, 30, 0.8), "white"),
               obj(3, "vehicle.car", static(10, -2.6), "red"), obj(4, "vehicle.car", static(17, -2.6), "white"),
               obj(5, "vehicle.car", static(30, -2.6), "silver", SIZES["suv"]),
               obj(6, "vehicle.car", static(55, 5.8, math.pi), "black"),
               obj(7, "vehicle.car", static(100, 5.8, math.pi), "blue"),
               obj(8, "vehicle.bus.rigid", static(80, 5.9, math.pi), "yellow", bus),
               obj(9, "vehicle.car", track_along(west, 130, 5), "grey"),
               obj(10, "human.pedestrian.child", track_along(line(70, 8, 70, -6), 0, 1.0), None, [0.4, 0.4, 1.3]),
               obj(11, "vehicle.car", static(140, -2.6), "white", VAN),
               obj(12, "vehicle.motorcycle", track_along(west, 40, 8), "red"),
               obj(13, "vehicle.car", track_along(east, 60 - 10, 4), "orange")]
    write("blind-school", "hand-made layout: a slow residential street by a school, the ego behind a cyclist, a "
          "school bus at the school, a car backing out of a driveway, parking alternating sides",
          lanes, east, 4.0, objects)


def main():
    rightturn()
    school()


if __name__ == "__main__":
    main()
