#!/usr/bin/env python3
"""Layouts of the blind set v28, each unlike every earlier one:
- blind-roadworks: a two-way road whose right eastbound lane is closed for 60 m by roadworks: cones,
  a digger, a dumper and a trailer standing in it, a worker beside it; traffic squeezes past in the
  left eastbound lane (the ego's) and oncoming traffic keeps coming.
- blind-fuel: a two-way road past a petrol station on the right: two pump lanes, a tanker bay, an
  entry and an exit road (a car waits there to pull out), parking on the far side of the road.
Run by make_layouts.py, or alone: python3 tests/data/layouts/layouts_v28.py (deterministic).
"""
from layout_lib import SIZES, lane, line, obj, static, track_along, write

DIGGER = [6.5, 2.6, 3.0]
TRAILER = [8.0, 2.5, 3.0]
TANKER = [11.0, 2.5, 3.5]
VAN = [5.2, 2.0, 2.1]


def roadworks():
    """Eastbound lanes y=-3.5 (closed from x=38 to x=95) and y=0 (the ego's), westbound y=3.5."""
    right, left = line(-60, -3.5, 220, -3.5), line(-60, 0, 220, 0)
    west = line(220, 3.5, -60, 3.5)
    lanes = [lane("eastbound_right", right), lane("eastbound_left", left), lane("westbound", west)]
    cones = [obj(3 + k, "movable_object.trafficcone", static(x, -1.95)) for k, x in enumerate((38, 48, 85, 95))]
    objects = [obj(1, "vehicle.construction", static(60, -3.5), "yellow", DIGGER),
               obj(2, "vehicle.truck", static(75, -3.5), "orange"), *cones,
               obj(7, "human.pedestrian.adult", track_along(line(52, -5.8, 70, -5.8), 0, 0.6)),
               obj(8, "vehicle.car", track_along(left, 60 + 22, 5), "white", VAN),
               obj(9, "vehicle.car", track_along(left, 60 - 15, 5), "red"),
               obj(10, "vehicle.car", track_along(west, 150, 8), "silver"),
               obj(11, "vehicle.bus.rigid", track_along(west, 90, 8), "blue"),
               obj(12, "vehicle.trailer", static(89, -3.5), "grey", TRAILER),
               obj(13, "vehicle.motorcycle", track_along(left, 60 - 30, 5.5), "black")]
    write("blind-roadworks", "hand-made layout: a two-way road with its right eastbound lane closed by roadworks "
          "(cones, a digger, a dumper, a trailer), traffic squeezing past, oncoming traffic", lanes, left, 5.0, objects)


def fuel():
    """Main road eastbound y=0 (the ego's), westbound y=3.5, parking on the far (left) side y=6.5;
    a petrol station on the right: pump lanes y=-9 and y=-13, a tanker bay y=-17 (x=30..55), an
    entry road from x=18 and an exit road back to the main road at x=62."""
    east, west = line(-60, 0, 220, 0), line(220, 3.5, -60, 3.5)
    lanes = [lane("main_eastbound", east), lane("main_westbound", west),
             lane("far_side_parking", line(-60, 6.5, 220, 6.5), 2.5, "parking"),
             lane("pump_lane_1", line(30, -9, 50, -9), 3.0, "parking"),
             lane("pump_lane_2", line(30, -13, 50, -13), 3.0, "parking"),
             lane("tanker_bay", line(30, -17, 55, -17), 3.5, "parking"),
             lane("station_entry", line(18, -1.75, 30, -9, 3.0), 3.5),
             lane("station_exit", line(50, -9, 62, -1.75, 3.0), 3.5)]
    objects = [obj(1, "vehicle.car", static(35, -9), "red"), obj(2, "vehicle.car", static(44, -9), "black", SIZES["suv"]),
               obj(3, "vehicle.motorcycle", static(33, -13), "blue"),
               obj(4, "vehicle.truck", static(42, -17), "white", TANKER),
               obj(5, "vehicle.car", static(58, -4.2, 0.55), "silver"),
               obj(6, "vehicle.car", track_along(east, 60 + 35, 8), "blue"),
               obj(7, "vehicle.car", track_along(west, 130, 9), "green", VAN),
               obj(8, "vehicle.car", track_along(west, 60, 9), "white"),
               obj(9, "vehicle.car", track_along(east, 60 - 20, 8), "yellow"),
               obj(10, "human.pedestrian.adult", track_along(line(40, -11, 40, -20), 0, 0.9)),
               obj(11, "vehicle.car", static(25, 6.5), "grey"), obj(12, "vehicle.car", static(100, 6.5), "black")]
    write("blind-fuel", "hand-made layout: a two-way road past a petrol station on the right (pump lanes, a tanker "
          "bay, entry and exit roads), parking on the far side", lanes, east, 8.0, objects)


def main():
    roadworks()
    fuel()


if __name__ == "__main__":
    main()
