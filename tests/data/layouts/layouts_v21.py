#!/usr/bin/env python3
"""Layouts of the blind set v21, each unlike every earlier one in how the map is drawn, not only in
its shape:
- blind-citynw: a two-way city street placed far from the world origin and turned so that the ego
  heads north-west; the oncoming lane and one side-street lane are drawn in the ego's order and
  marked "backward" (as map converters often write them).
- blind-hilllane: a single-track country lane used both ways ("both") climbing a 7 % hill, with
  passing places, a farm track, a tractor (vehicle.construction) and a horse (animal).
- blind-boulevard: a boulevard, three lanes each way, tram tracks in the median (lane type "tram"),
  service roads with parking on both sides, a cycle track (type "bicycle"), a tram, a bendy bus
  and an articulated lorry (vehicle.trailer).
Run by make_layouts.py, or alone: python3 tests/data/layouts/layouts_v21.py (deterministic).
"""
import math

from layout_lib import SIZES, Placement, lane, line, obj, static, track_along, write

VAN = [5.2, 2.0, 2.1]


def back(ln):
    """A lane drawn against its traffic (direction "backward")."""
    return dict(ln, direction="backward")


def city_north_west():
    """Local frame: the ego's lane y=0 east, the oncoming lane y=3.5 drawn west-to-east and marked
    backward; kerb parking on the right (y=-3.0) broken by a side street to the right at x=41
    (out x=39.25 southward, in x=42.75 drawn southward and marked backward); a pavement on the left.
    Placed at (2400, -1300), turned 135 deg: the ego heads north-west."""
    main, opposite = line(-60, 0, 220, 0), line(-60, 3.5, 220, 3.5)
    lanes = [lane("main_nw", main), back(lane("main_se", opposite)),
             lane("kerb_parking_a", line(-60, -3.0, 30, -3.0), 2.5, "parking"),
             lane("kerb_parking_b", line(52, -3.0, 220, -3.0), 2.5, "parking"),
             lane("side_out", line(39.25, -1.75, 39.25, -150)), back(lane("side_in", line(42.75, -1.75, 42.75, -150)))]
    oncoming = list(reversed(opposite))
    objects = [obj(1, "vehicle.car", track_along(main, 95, 7), "silver"),
               obj(2, "vehicle.bus.rigid", track_along(oncoming, 150, 9), "blue"),
               obj(3, "vehicle.car", static(12, -3.0), "white"), obj(4, "vehicle.car", static(65, -3.0), "black"),
               obj(5, "vehicle.car", static(80, -3.0), "red", SIZES["suv"]),
               obj(6, "vehicle.truck", static(110, -3.0), "yellow"),
               obj(7, "vehicle.bicycle", track_along(main, 75, 4), "green"),
               obj(8, "vehicle.car", track_along(line(42.75, -150, 42.75, -1.75), 100, 4.8), "orange"),
               obj(9, "human.pedestrian.adult", track_along(line(-60, 6.5, 220, 6.5), 70, 1.3))]
    write("blind-citynw", "hand-made layout: a two-way city street far from the world origin, the ego heading "
          "north-west, lanes drawn against their traffic marked backward", lanes, main, 6, objects,
          Placement(135.0, 2400.0, -1300.0))


def hill_lane():
    """A single-track lane (4.5 m, used both ways) east from x=-60 climbing 7 % from x=0 to x=140;
    passing places on the right (x 55..70) and on the left (x 150..165); a farm track leaving to the
    left at x=100 (3 m, both ways)."""
    road = line(-60, 0, 260, 0)
    lanes = [lane("single_track", road, 4.5, "driving") | {"direction": "both"},
             lane("passing_place_1", line(55, -3.5, 70, -3.5), 2.5, "parking"),
             lane("passing_place_2", line(150, 3.5, 165, 3.5), 2.5, "parking"),
             lane("farm_track", line(100, 2.25, 100, 150), 3.0) | {"direction": "both"}]
    down = list(reversed(road))
    objects = [obj(1, "vehicle.construction", track_along(road, 100, 2.5), "green", [4.2, 2.4, 2.9]),
               obj(2, "vehicle.car", static(157, 3.5, math.pi), "red"),
               obj(3, "vehicle.car", track_along(down, 60, 4), "blue"),
               obj(4, "vehicle.car", static(62, -3.5), "white", VAN),
               obj(5, "animal", track_along(line(-60, -1.5, 260, -1.5), 85, 1.5), None, [2.4, 0.8, 2.4]),
               obj(6, "human.pedestrian.adult", track_along(line(101, 60, 101, 2), 0, 1.2)),
               obj(7, "vehicle.car", static(100, 12, -math.pi / 2), "silver"),
               obj(8, "vehicle.motorcycle", track_along(road, 45, 5), "black")]
    write("blind-hilllane", "hand-made layout: a single-track country lane used both ways, climbing a 7 % hill, "
          "with passing places and a farm track", lanes, road, 5, objects,
          Placement(ground=lambda x, y: 0.07 * min(max(x, 0.0), 140.0)))


def boulevard():
    """Three lanes east (y=-3.5 kerbside, y=0 the ego's, y=3.5), tram tracks in the median (y=7.5
    east, y=10.5 west), three lanes west (y=14.5, 18, 21.5 kerbside); service roads: south one-way
    east (y=-10) with parking (y=-13) and a two-way cycle track (y=-7), north one-way west (y=25)
    with parking (y=28); a cross street at x=120 (northbound x=121.75, southbound x=118.25)."""
    east = {y: line(-60, y, 260, y) for y in (-3.5, 0.0, 3.5)}
    west = {y: line(260, y, -60, y) for y in (14.5, 18.0, 21.5)}
    lanes = [lane("east_kerb", east[-3.5]), lane("east_middle", east[0.0]), lane("east_fast", east[3.5]),
             lane("tram_east", line(-60, 7.5, 260, 7.5), 3.0, "tram"),
             lane("tram_west", line(260, 10.5, -60, 10.5), 3.0, "tram"),
             lane("west_fast", west[14.5]), lane("west_middle", west[18.0]), lane("west_kerb", west[21.5]),
             lane("service_south", line(-60, -10, 260, -10)), lane("service_south_parking", line(-60, -13, 110, -13), 2.5, "parking"),
             lane("cycle_track", line(-60, -7, 260, -7), 2.0, "bicycle") | {"direction": "both"},
             lane("service_north", line(260, 25, -60, 25)), lane("service_north_parking", line(260, 28, -60, 28), 2.5, "parking"),
             lane("cross_nb", line(121.75, -200, 121.75, 200)), lane("cross_sb", line(118.25, 200, 118.25, -200))]
    objects = [obj(1, "vehicle.tram", track_along(line(-60, 7.5, 260, 7.5), 80, 8), "white", [30.0, 2.65, 3.4]),
               obj(2, "vehicle.bus.bendy", track_along(east[-3.5], 110, 7), "red", [18.0, 2.55, 3.2]),
               obj(3, "vehicle.trailer", track_along(east[3.5], 40, 11), "grey", [13.0, 2.5, 3.8]),
               obj(4, "vehicle.car", track_along(east[0.0], 95, 9), "black"),
               obj(5, "vehicle.car", static(20, -13), "blue"), obj(6, "vehicle.car", static(45, -13), "white"),
               obj(7, "vehicle.car", static(70, -13), "yellow"),
               obj(8, "vehicle.car", track_along(line(-60, -10, 260, -10), 70, 5), "green"),
               obj(9, "vehicle.car", track_along(west[14.5], 110, 12), "silver"),
               obj(10, "vehicle.bus.rigid", track_along(west[21.5], 170, 8), "yellow"),
               obj(11, "vehicle.bicycle", track_along(line(-60, -7, 260, -7), 60, 4), "orange"),
               obj(12, "vehicle.emergency.police", static(121.75, -20, math.pi / 2), "white")]
    write("blind-boulevard", "hand-made layout: a boulevard with tram tracks in the median, service roads with "
          "parking and a cycle track", lanes, east[0.0], 9, objects)


def main():
    city_north_west()
    hill_lane()
    boulevard()


if __name__ == "__main__":
    main()
