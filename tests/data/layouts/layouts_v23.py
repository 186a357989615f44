#!/usr/bin/env python3
"""Layouts of the blind set v23, each unlike every earlier one in the traffic the ego is in:
- blind-queue: the ego stands still, third in a queue at a red light before a crossroads, with a
  queue beside it in the left lane, a car queued behind it, a motorbike filtering between the
  queues, moving oncoming and crossing traffic, pedestrians on the crossing.
- blind-carpark: a supermarket car park: the ego creeps along a two-way aisle (one "both" lane
  6 m wide) between perpendicular bays, a cross aisle, a car reversing out of its bay, a car
  coming the other way, shoppers walking in the aisle, a delivery truck across three bays.
Run by make_layouts.py, or alone: python3 tests/data/layouts/layouts_v23.py (deterministic).
"""
import math

from layout_lib import FRAMES, HZ, SIZES, lane, line, obj, static, track_along, write

VAN = [5.2, 2.0, 2.1]
NORTH, SOUTH = math.pi / 2, -math.pi / 2


def queue():
    """Two lanes each way (east y=0 the ego's, y=3.5; west y=7, y=10.5), a stop line at x=22 before
    a crossroads at x=30 (northbound x=31.75, southbound x=28.25), kerb parking on the right after
    the junction (y=-3.25, x 40..200). The ego stands at x=0."""
    east = {y: line(-80, y, 200, y) for y in (0.0, 3.5)}
    west = {y: line(200, y, -80, y) for y in (7.0, 10.5)}
    lanes = [lane("east_kerb", east[0.0]), lane("east_inner", east[3.5]),
             lane("west_inner", west[7.0]), lane("west_kerb", west[10.5]),
             lane("cross_north", line(31.75, -90, 31.75, 90)), lane("cross_south", line(28.25, 90, 28.25, -90)),
             lane("kerb_parking", line(40, -3.25, 200, -3.25), 2.5, "parking")]
    objects = [obj(1, "vehicle.car", static(8.0, 0.0), "white", VAN),
               obj(2, "vehicle.car", static(15.5, 0.0), "red"),
               obj(3, "vehicle.car", static(14.0, 3.5), "black", SIZES["suv"]),
               obj(4, "vehicle.car", static(1.0, 3.5), "blue"),
               obj(5, "vehicle.car", static(-7.0, 0.0), "grey"),
               obj(6, "vehicle.bus.rigid", track_along(west[10.5], 80, 6), "green"),
               obj(7, "vehicle.car", track_along(west[7.0], 140, 9), "yellow"),
               obj(8, "vehicle.car", track_along(line(31.75, -90, 31.75, 90), 20, 8), "silver"),
               obj(9, "human.pedestrian.adult", track_along(line(24, -6, 24, 16), 3, 1.3)),
               obj(10, "human.pedestrian.adult", track_along(line(-60, -4, 200, -4), 70, 1.2)),
               obj(11, "vehicle.motorcycle", track_along(line(-80, 1.75, 200, 1.75), 60, 2.5), "orange"),
               obj(12, "vehicle.car", static(55, -3.25), "orange"),
               obj(13, "vehicle.truck", static(75, -3.25), "white")]
    write("blind-queue", "hand-made layout: the ego stopped third in a queue at a red light before a crossroads, "
          "a queue beside it, a motorbike filtering", lanes, line(-80, 0, 200, 0), 0.0, objects)


def reversing_out(x, y, start_frame, speed):
    """A car nose-in in a bay facing north (+y), reversing south out of it from start_frame (after the car
    coming down the aisle has passed: a recording never holds two vehicles in one place)."""
    out = []
    for f in range(FRAMES):
        back = max(0.0, (f - start_frame) / HZ * speed)
        out.append({"frame": f, "center": [x, round(y - min(back, 4.5), 3), 0.8], "yaw": NORTH})
    return out


def carpark():
    """An aisle along +x (centre y=1.5, 6 m, two-way "both"); the ego keeps right at y=0 at 3 m/s.
    Perpendicular bays 5 m deep both sides (right centre y=-4, left y=7), broken by a cross aisle
    at x=80 (6 m, both ways, north-south); a second row of bays along the cross aisle's east side."""
    aisle = line(-60, 1.5, 160, 1.5)
    lanes = [lane("aisle", aisle, 6.0) | {"direction": "both"},
             lane("cross_aisle", line(80, -60, 80, 60), 6.0) | {"direction": "both"},
             lane("bays_right_a", line(-60, -4, 76, -4), 5.0, "parking"),
             lane("bays_right_b", line(84, -4, 160, -4), 5.0, "parking"),
             lane("bays_left_a", line(-60, 7, 76, 7), 5.0, "parking"),
             lane("bays_left_b", line(84, 7, 160, 7), 5.0, "parking")]
    car = SIZES["vehicle.car"]
    objects = [obj(1, "vehicle.car", static(10, -4, SOUTH), "red"),
               obj(2, "vehicle.car", static(13, -4, SOUTH), "white", SIZES["suv"]),
               obj(3, "vehicle.car", static(20, 7, NORTH), "black"),
               obj(4, "vehicle.car", reversing_out(35, 7, 75, 1.0), "blue"),
               obj(5, "vehicle.car", static(40, -4, SOUTH), "silver"),
               obj(6, "vehicle.car", static(43, -4, NORTH), "grey", VAN),
               obj(7, "vehicle.car", track_along(line(160, 3, -60, 3), 105, 3), "green"),
               obj(8, "vehicle.car", static(60, 7, NORTH), "yellow"),
               obj(9, "human.pedestrian.adult", track_along(line(160, -1.2, -60, -1.2), 130, 1.1)),
               obj(10, "human.pedestrian.adult", track_along(line(50, -10, 50, 14), 5, 1.2)),
               obj(11, "vehicle.motorcycle", static(8, 7, NORTH), "black"),
               obj(12, "vehicle.truck", static(100, -4), "white"),
               obj(13, "vehicle.car", static(70, -4, SOUTH), "black", car),
               obj(14, "vehicle.car", static(90, 7, NORTH), "red"),
               obj(15, "vehicle.car", track_along(line(-60, 0, 160, 0), 47, 3), "silver")]
    write("blind-carpark", "hand-made layout: a supermarket car park, a two-way aisle between perpendicular bays, "
          "a cross aisle, a car reversing out of its bay", lanes, line(-60, 0, 160, 0), 3.0, objects)


def main():
    queue()
    carpark()


if __name__ == "__main__":
    main()
