#!/usr/bin/env python3
"""Layouts of the blind set v29, each unlike every earlier one:
- blind-busway: a city street with a two-way busway in its middle (bus-only lanes between the general
  lanes), an articulated bus standing at a stop in it, a cycle lane and a loading bay on the right.
- blind-tollplaza: a motorway whose two lanes fan out into four toll booths and merge back after
  them; cars and a truck wait at the booths, the ego approaches the second booth from the left;
  the opposite carriageway lies beyond a median.
Run by make_layouts.py, or alone: python3 tests/data/layouts/layouts_v29.py (deterministic).
"""
from layout_lib import SIZES, lane, line, obj, static, track_along, write

BENDY = [18.0, 2.55, 3.2]
VAN = [5.2, 2.0, 2.1]


def busway():
    """General eastbound y=0 (the ego's), busway eastbound y=3.5 and westbound y=8.5 with a stop's
    platform between them (y=6), general westbound y=12; a cycle lane y=-2.75 and a loading bay
    y=-4.75 (x=90..112) on the right."""
    east, west = line(-60, 0, 220, 0), line(220, 12, -60, 12)
    bus_east, bus_west = line(-60, 3.5, 220, 3.5), line(220, 8.5, -60, 8.5)
    cycle = line(-60, -2.75, 220, -2.75)
    lanes = [lane("general_eastbound", east), lane("busway_eastbound", bus_east), lane("busway_westbound", bus_west),
             lane("general_westbound", west), lane("cycle_lane", cycle, 1.5, "bicycle"),
             lane("loading_bay", line(90, -4.75, 112, -4.75), 2.5, "parking")]
    objects = [obj(1, "vehicle.bus.bendy", static(70, 3.5), "red", BENDY),
               obj(2, "vehicle.bus.rigid", track_along(bus_west, 220 - 150, 9), "blue"),
               obj(3, "vehicle.car", track_along(east, 60 + 25, 8), "white"),
               obj(4, "vehicle.car", track_along(east, 60 - 18, 8), "black"),
               obj(5, "vehicle.car", track_along(west, 220 - 120, 10), "yellow"),
               obj(6, "vehicle.car", static(100, -4.75), "white", VAN),
               obj(7, "vehicle.bicycle", track_along(cycle, 60 + 10, 4)),
               obj(8, "human.pedestrian.adult", track_along(line(60, 6, 80, 6), 0, 0.7)),
               obj(9, "vehicle.motorcycle", track_along(west, 220 - 60, 10), "red"),
               obj(10, "vehicle.car", track_along(west, 220 - 200, 10), "silver")]
    write("blind-busway", "hand-made layout: a city street with a two-way busway in its middle, an articulated bus "
          "at a stop, a cycle lane and a loading bay on the right", lanes, east, 8.0, objects)


def fan(y_in, y_booth, y_out):
    """A lane from the approach (y_in) through a booth (y_booth, x=65..100) to the exit (y_out)."""
    return (line(-60, y_in, 45, y_in)[:-1] + line(45, y_in, 65, y_booth)[:-1] + line(65, y_booth, 100, y_booth)[:-1]
            + line(100, y_booth, 120, y_out)[:-1] + line(120, y_out, 260, y_out))


def tollplaza():
    """Approach lanes y=0 (the ego's) and y=-3.5 fan into booths at y=5.25, 1.75, -1.75, -5.25 and merge
    back to y=0 and y=-3.5; westbound lanes y=12 and y=15.5 beyond a median."""
    booths = [fan(0, 5.25, 0), fan(0, 1.75, 0), fan(-3.5, -1.75, -3.5), fan(-3.5, -5.25, -3.5)]
    lanes = [lane(f"booth_{k + 1}", pts) for k, pts in enumerate(booths)]
    west_1, west_2 = line(260, 12, -60, 12), line(260, 15.5, -60, 15.5)
    lanes += [lane("westbound_1", west_1), lane("westbound_2", west_2)]
    ego = booths[1]
    objects = [obj(1, "vehicle.car", static(88, 5.25), "red"),
               obj(2, "vehicle.truck", static(88, -1.75), "white"),
               obj(3, "vehicle.car", static(78.5, -1.75), "blue"),
               obj(4, "vehicle.car", static(88, -5.25), "black", SIZES["suv"]),
               obj(5, "vehicle.car", track_along(booths[3], 60 + 20, 6), "silver"),
               obj(6, "vehicle.motorcycle", track_along(ego, 60 - 15, 6), "black"),
               obj(7, "vehicle.car", track_along(booths[0], 60 + 140, 12), "green"),
               obj(8, "human.pedestrian.adult", static(92, 3.5)),
               obj(9, "vehicle.car", track_along(west_1, 260 - 150, 20), "white"),
               obj(10, "vehicle.truck", track_along(west_2, 260 - 60, 18), "orange")]
    write("blind-tollplaza", "hand-made layout: a motorway fanning out into four toll booths and merging back, "
          "vehicles waiting at the booths, the opposite carriageway beyond a median", lanes, ego, 6.0, objects)


def main():
    busway()
    tollplaza()


if __name__ == "__main__":
    main()
