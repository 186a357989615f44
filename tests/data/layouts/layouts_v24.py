#!/usr/bin/env python3
"""Layouts of the blind set v24, each unlike every earlier one:
- blind-giveway: the ego comes up a minor road to a T junction with a four-lane main road and
  turns left onto it within the clip (its own path bends 90 degrees); kerb parking on the minor
  road, a bus at a stop on the main road's far side, a cyclist ahead of the ego on its path.
- blind-twltl: a US suburban arterial, two lanes each way with a centre two-way left-turn lane
  (one lane used both ways) between them, a driveway into a strip-mall parking lot on the right
  and one into a gas station on the left.
Run by make_layouts.py, or alone: python3 tests/data/layouts/layouts_v24.py (deterministic).
"""
import math

from layout_lib import FRAMES, HZ, SIZES, lane, line, obj, static, track_along, write

VAN = [5.2, 2.0, 2.1]
PICKUP = [5.4, 2.0, 1.9]
NORTH, SOUTH, WEST = math.pi / 2, -math.pi / 2, math.pi


def arc(cx, cy, r, a0, a1, n=12):
    return [[cx + r * math.cos(a0 + (a1 - a0) * k / n), cy + r * math.sin(a0 + (a1 - a0) * k / n), 0.0]
            for k in range(n + 1)]


def left_turn_path():
    """The ego's path: along the minor road (y=0) to x=44, a quarter turn left of radius 10.75 into
    the main road's northbound inner lane (x=54.75), then north."""
    return line(-60, 0, 44, 0) + arc(44, 10.75, 10.75, -math.pi / 2, 0)[1:] + line(54.75, 15, 54.75, 200)[1:]


def giveway():
    """Minor road along +x: the ego's lane y=0, the oncoming lane y=3.2 (both 3.2 wide), kerb parking
    both sides (y=-2.85 right, y=6.05 left) up to x=36. The main road runs north-south at x=46..60:
    southbound x=47.75 (kerb) and 51.25, northbound 54.75 and 58.25; a bus stop bay on the far side
    (x=61.5, y 20..45)."""
    minor_in, minor_out = line(-60, 0, 44, 0), line(44, 3.2, -60, 3.2)
    south = {x: line(x, 200, x, -200) for x in (47.75, 51.25)}
    north = {x: line(x, -200, x, 200) for x in (54.75, 58.25)}
    ego_path = left_turn_path()
    lanes = [lane("minor_in", minor_in, 3.2), lane("minor_out", minor_out, 3.2),
             lane("south_kerb", south[47.75]), lane("south_inner", south[51.25]),
             lane("north_inner", north[54.75]), lane("north_kerb", north[58.25]),
             lane("minor_parking_right", line(-60, -2.85, 36, -2.85), 2.5, "parking"),
             lane("minor_parking_left", line(-60, 6.05, 36, 6.05), 2.5, "parking"),
             lane("bus_stop", line(61.5, 20, 61.5, 45), 3.0, "parking")]
    objects = [obj(1, "vehicle.car", static(15, -2.85), "red"),
               obj(2, "vehicle.car", static(24, -2.85), "white", VAN),
               obj(3, "vehicle.car", track_along(minor_out, 6, 5), "black"),
               obj(4, "vehicle.car", track_along(south[51.25], 140, 12), "silver"),
               obj(5, "vehicle.car", track_along(north[54.75], 70, 11), "blue", SIZES["suv"]),
               obj(6, "vehicle.bus.rigid", static(61.5, 32, NORTH), "green"),
               obj(7, "vehicle.car", track_along(north[58.25], 180, 9), "yellow"),
               obj(8, "vehicle.truck", track_along(south[47.75], 60, 7), "white"),
               obj(9, "vehicle.bicycle", track_along(ego_path, 60 + 26, 4.5)),
               obj(10, "human.pedestrian.adult", track_along(line(20, 9, 20, -8), 0, 1.2)),
               obj(11, "vehicle.motorcycle", track_along(north[58.25], 70, 14), "black"),
               obj(12, "vehicle.car", static(9, 6.05, WEST), "orange")]
    write("blind-giveway", "hand-made layout: a minor road up to a T junction with a four-lane main road, "
          "the ego turning left onto it, a bus at a stop on the far side", lanes, ego_path, 6.0, objects)


def twltl():
    """Eastbound y=0 (kerb, the ego's) and 3.5, a centre two-way left-turn lane y=7.05 (3.6 wide, used
    both ways), westbound 10.6 and 14.1. A two-way driveway south at x=70 into a strip-mall lot (aisle
    y=-30, parking rows y=-25 and y=-35); a two-way driveway north at x=110 into a gas station."""
    east = {y: line(-80, y, 260, y) for y in (0.0, 3.5)}
    west = {y: line(260, y, -80, y) for y in (10.6, 14.1)}
    lanes = [lane("east_kerb", east[0.0]), lane("east_inner", east[3.5]),
             lane("centre_turn", line(-80, 7.05, 260, 7.05), 3.6) | {"direction": "both"},
             lane("west_inner", west[10.6]), lane("west_kerb", west[14.1]),
             lane("mall_driveway", line(70, -1.75, 70, -30), 6.0) | {"direction": "both"},
             lane("mall_aisle", line(40, -30, 130, -30), 6.0) | {"direction": "both"},
             lane("mall_row_north", line(40, -25, 130, -25), 5.0, "parking"),
             lane("mall_row_south", line(40, -35, 130, -35), 5.0, "parking"),
             lane("gas_driveway", line(110, 15.85, 110, 45), 6.0) | {"direction": "both"}]
    objects = [obj(1, "vehicle.car", static(68, 7.05, WEST), "white", PICKUP),
               obj(2, "vehicle.car", track_along(east[0.0], 80 + 30, 12), "red"),
               obj(3, "vehicle.car", track_along(east[3.5], 80 - 15, 15), "black", SIZES["suv"]),
               obj(4, "vehicle.car", track_along(west[10.6], 260 - 150, 13), "grey"),
               obj(5, "vehicle.car", track_along(west[14.1], 260 - 90, 11), "silver", VAN),
               obj(6, "vehicle.car", static(80, -25, NORTH), "blue"),
               obj(7, "vehicle.bus.rigid", track_along(west[14.1], 260 - 230, 10), "yellow"),
               obj(8, "vehicle.car", static(110, 20, SOUTH), "orange"),
               obj(9, "human.pedestrian.adult", track_along(line(-80, -3.2, 260, -3.2), 100, 1.3)),
               obj(10, "vehicle.car", track_along(line(130, -30, 40, -30), 20, 3), "green"),
               obj(11, "vehicle.motorcycle", track_along(east[0.0], 80 - 25, 14), "red"),
               obj(12, "vehicle.car", static(95, -35, SOUTH), "black"),
               obj(13, "vehicle.truck", static(120, -25, NORTH), "white")]
    write("blind-twltl", "hand-made layout: a US suburban arterial, two lanes each way and a centre two-way "
          "left-turn lane, driveways to a strip mall and a gas station", lanes, line(-80, 0, 260, 0), 13.0,
          objects)


def main():
    giveway()
    twltl()


if __name__ == "__main__":
    main()
