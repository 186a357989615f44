#!/usr/bin/env python3
"""Layouts of the blind set v30, each unlike every earlier one:
- blind-levelcrossing: a two-lane country road crossing a railway (lane type "rail") at x=78, two
  vehicles waiting at the lowered barrier in the ego's lane, a tractor and a motorbike coming the
  other way, a lay-by across the road and a farm track leaving to the right.
- blind-drivethru: a two-way street with a fast-food drive-thru to the right: a one-way lane that
  leaves the street, runs past the order window with cars queuing at it, loops round the building
  and comes back out by an exit lane; a small car park beside the building.
Run by make_layouts.py, or alone: python3 tests/data/layouts/layouts_v30.py (deterministic).
"""
from layout_lib import SIZES, joined, lane, line, obj, static, track_along, write

TRACTOR = [4.0, 2.3, 2.8]
VAN = [5.2, 2.0, 2.1]
PICKUP = [5.4, 2.0, 1.9]


def levelcrossing():
    """Eastbound y=0 (the ego's), westbound y=3.5; the railway runs north-south at x=78; a lay-by
    y=6.75 (x=25..50) across the road; a farm track leaves to the right at x=40, heading south."""
    east, west = line(-60, 0, 220, 0), line(220, 3.5, -60, 3.5)
    farm = joined((36, -1.75), (40, -6), (40, -70))
    lanes = [lane("eastbound", east), lane("westbound", west), lane("railway", line(78, -80, 78, 80), 3.0, "rail"),
             lane("lay_by", line(25, 6.75, 50, 6.75), 2.5, "parking"), lane("farm_track", farm, 3.0)]
    objects = [obj(1, "vehicle.car", static(71, 0), "red"),
               obj(2, "vehicle.car", static(64, 0), "white", VAN),
               obj(3, "vehicle.construction", track_along(west, 220 - 130, 3), "green", TRACTOR),
               obj(4, "vehicle.motorcycle", track_along(west, 220 - 30, 14), "black"),
               obj(5, "vehicle.car", static(38, 6.75, 3.14159), "silver"),
               obj(6, "human.pedestrian.adult", track_along(line(10, -3, 80, -3), 0, 1.2)),
               obj(7, "vehicle.bicycle", track_along(east, 60 + 22, 3.5)),
               obj(8, "vehicle.car", static(40, -40, -1.5708), "black", SIZES["suv"])]
    write("blind-levelcrossing", "hand-made layout: a two-lane country road crossing a railway, two vehicles waiting "
          "at the barrier, a tractor coming the other way, a lay-by and a farm track", lanes, east, 4.5, objects)


def drivethru():
    """Eastbound y=0 (the ego's), westbound y=3.5; the drive-thru leaves at x=35, runs east along
    y=-12 past the window (x=95), loops round the building's east end and back west along y=-48 to
    the exit lane, which rejoins the street at x=5; car park bays y=-30, x=50..95."""
    east, west = line(-60, 0, 220, 0), line(220, 3.5, -60, 3.5)
    thru = joined((35, -1.75), (45, -12), (100, -12), (110, -22), (110, -40), (100, -48), (20, -48))
    exit_lane = joined((20, -48), (12, -40), (12, -8), (5, -1.75))
    lanes = [lane("eastbound", east), lane("westbound", west), lane("drive_thru", thru), lane("drive_thru_exit", exit_lane),
             lane("car_park", line(50, -30, 95, -30), 2.5, "parking")]
    objects = [obj(1, "vehicle.car", static(95, -12), "white"),
               obj(2, "vehicle.car", static(88.5, -12), "red"),
               obj(3, "vehicle.car", static(81.5, -12), "blue", PICKUP),
               obj(4, "vehicle.car", track_along(east, 60 + 20, 8), "black"),
               obj(5, "vehicle.car", static(60, -30, 1.5708), "silver"),
               obj(6, "vehicle.motorcycle", track_along(west, 220 - 150, 10), "red"),
               obj(7, "human.pedestrian.adult", track_along(line(70, -26, 70, -40), 0, 1.0)),
               obj(8, "vehicle.truck", track_along(west, 220 - 40, 10), "yellow")]
    write("blind-drivethru", "hand-made layout: a two-way street with a fast-food drive-thru to the right, cars "
          "queuing at its window, an exit lane back to the street and a small car park", lanes, east, 8.0, objects)


def main():
    levelcrossing()
    drivethru()


if __name__ == "__main__":
    main()
