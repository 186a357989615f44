#!/usr/bin/env python3
"""Layouts of the blind sets v19 and v20, none like an earlier one. v19: a motorway, three lanes
each way with a hard shoulder (lane type "shoulder", which no earlier layout has) and an exit slip
road; a grid of one-way streets, a contraflow cycle lane and a delivery truck stopped in the ego's lane; a road whose left
lane ends (drawn tapering into the right one) with a driveway into a car park on the right. v20:
a one-way road whose left lane forks off to the north-east; a two-way street with a zebra
crossing, a cycle lane and a bus stop bay.
Run by make_layouts.py, or alone: python3 tests/data/layouts/more_layouts.py (deterministic).
"""
import math

from layout_lib import SIZES, lane, line, obj, static, track_along, write


def motorway():
    """Three lanes each way (ego in the middle one, y=0; slow lane y=-3.5, fast lane y=3.5), a hard
    shoulder at y=-6.75, a central reservation, westbound lanes y=10..17; an exit slip road leaving
    the slow lane from x=150 to the right."""
    east = {y: line(-60, y, 400, y, 10) for y in (-3.5, 0.0, 3.5)}
    west = {y: line(400, y, -60, y, 10) for y in (10.0, 13.5, 17.0)}
    slip = line(150, -3.5, 190, -8.0, 5) + line(195, -9.0, 300, -30.0, 10)[0:]
    lanes = [lane("eb_lane_1", east[-3.5]), lane("eb_lane_2", east[0.0]), lane("eb_lane_3", east[3.5]),
             lane("hard_shoulder", line(-60, -6.75, 400, -6.75, 10), 3.0, "shoulder"),
             lane("wb_lane_1", west[17.0]), lane("wb_lane_2", west[13.5]), lane("wb_lane_3", west[10.0]),
             lane("exit_slip", slip, 3.5)]
    objects = [obj(1, "vehicle.truck", track_along(east[-3.5], 95, 20), "white"),
               obj(2, "vehicle.car", track_along(east[3.5], 40, 28), "black"),
               obj(3, "vehicle.car", static(75, -6.75), "yellow"),
               obj(4, "vehicle.emergency.police", static(62, -6.75), "white"),
               obj(5, "vehicle.car", track_along(east[0.0], 115, 22), "red"),
               obj(6, "vehicle.bus.rigid", track_along(west[10.0], 300, 24), "blue"),
               obj(7, "vehicle.car", track_along(west[13.5], 240, 30), "green"),
               obj(8, "vehicle.motorcycle", track_along(east[0.0], 25, 22), "orange"),
               obj(9, "vehicle.truck", track_along(east[-3.5], 20, 19), "grey")]
    write("blind-motorway", "hand-made layout: motorway, three lanes each way, a hard shoulder and an exit slip road",
          lanes, east[0.0], 22, objects)


def one_way_grid():
    """The ego's one-way street (east, two lanes: y=0, y=3.5 the ego's), parking both sides (y=-3.0 and
    y=8.75), a contraflow cycle lane (west, y=6.25) on the left; at x=45 a one-way street crossing
    northbound (two lanes, x=43.25 and x=46.75), no way south."""
    east = line(-60, 0, 200, 0)
    lanes = [lane("main_right", east), lane("main_left", line(-60, 3.5, 200, 3.5)),
             lane("cycle_contraflow", line(200, 6.25, -60, 6.25), 1.5),
             lane("parking_south_a", line(-60, -3.0, 38, -3.0), 2.5, "parking"),
             lane("parking_south_b", line(52, -3.0, 200, -3.0), 2.5, "parking"),
             lane("parking_north_a", line(-60, 8.75, 38, 8.75), 2.5, "parking"),
             lane("parking_north_b", line(52, 8.75, 200, 8.75), 2.5, "parking"),
             lane("cross_left", line(43.25, -90, 43.25, 120)), lane("cross_right", line(46.75, -90, 46.75, 120))]
    objects = [obj(1, "vehicle.truck", static(28, 0.0), "white"),
               obj(2, "vehicle.bicycle", track_along(line(200, 6.25, -60, 6.25), 150, 4.5), "green"),
               obj(3, "vehicle.car", static(15, -3.0), "blue"), obj(4, "vehicle.car", static(62, -3.0), "black"),
               obj(5, "vehicle.car", static(10, 8.75), "silver"), obj(6, "vehicle.car", static(70, 8.75), "red"),
               obj(7, "vehicle.car", track_along(line(-60, 3.5, 200, 3.5), 75, 3), "yellow"),
               obj(8, "vehicle.car", track_along(line(46.75, -90, 46.75, 120), 60, 7), "orange"),
               obj(9, "human.pedestrian.adult", track_along(line(56, -6, 56, 12), 0, 1.2)),
               obj(10, "vehicle.bus.rigid", track_along(line(43.25, -90, 43.25, 120), 20, 5), "grey")]
    write("blind-onewaygrid", "hand-made layout: one-way streets crossing, a contraflow cycle lane, a delivery truck "
          "stopped in the ego's lane", lanes, line(-60, 3.5, 200, 3.5), 4, objects)


def taper(x0, x1, y0, y1, step=5.0):
    """A lane moving from y0 to y1 between x0 and x1 (a smooth lane drop)."""
    n = int((x1 - x0) / step)
    return [[x0 + (x1 - x0) * k / n, y0 + (y1 - y0) * (1 - math.cos(math.pi * k / n)) / 2, 0.0] for k in range(n + 1)]


def lane_drop():
    """Two lanes east (ego in the right one, y=0), the left one (y=3.5) ends at x=80, tapering into the
    right one by x=110; one lane west (y=7.25); a driveway on the right at x=40 into a car park whose
    bays run along y=-22 (x 25..75)."""
    left = line(-60, 3.5, 80, 3.5)[:-1] + taper(80, 110, 3.5, 0.0)
    lanes = [lane("eb_right", line(-60, 0, 220, 0)), lane("eb_left_ends", left),
             lane("wb", line(220, 7.25, -60, 7.25)),
             lane("driveway_in", line(38.25, -1.75, 38.25, -18.0), 3.0), lane("driveway_out", line(41.75, -18.0, 41.75, -1.75), 3.0),
             lane("car_park_aisle", line(25, -19.5, 75, -19.5), 3.0, "driving"),
             lane("car_park_bays", line(25, -23.0, 75, -23.0), 2.5, "parking")]
    objects = [obj(1, "vehicle.car", static(30, -23.0), "white"), obj(2, "vehicle.car", static(55, -23.0), "red"),
               obj(3, "vehicle.car", track_along(line(41.75, -18.0, 41.75, -1.75), 0, 1.5), "blue"),
               obj(4, "vehicle.truck", track_along(line(-60, 0, 220, 0), 100, 7), "grey"),
               obj(5, "vehicle.car", track_along(left, 75, 8), "black"),
               obj(6, "vehicle.bus.rigid", track_along(line(220, 7.25, -60, 7.25), 130, 8), "yellow"),
               obj(7, "human.pedestrian.adult", track_along(line(34, -12, 34, -30), 0, 1.0)),
               obj(8, "vehicle.car", track_along(line(-60, 0, 220, 0), 45, 8), "silver"),
               obj(9, "vehicle.motorcycle", track_along(left, 50, 9), "black")]
    write("blind-lanedrop", "hand-made layout: the left lane ends and tapers into the right one; a driveway into a "
          "car park on the right", lanes, line(-60, 0, 220, 0), 8, objects)


def fork():
    """A one-way road east, two lanes (ego in the right one, y=0), whose left lane bears left at x=60
    into a branch heading 30 deg north-east while the right lane runs on east; parking on the right
    to x=50. Written for set v20."""
    arc = [[60 + 60 * math.sin(math.radians(a)), 63.5 - 60 * math.cos(math.radians(a)), 0.0] for a in range(5, 31, 5)]
    end = arc[-1]
    branch = line(-60, 3.5, 60, 3.5)[:-1] + [[60.0, 3.5, 0.0]] + arc + [
        [end[0] + 120 * math.cos(math.radians(30)), end[1] + 120 * math.sin(math.radians(30)), 0.0]]
    east = line(-60, 0, 220, 0)
    lanes = [lane("east_through", east), lane("north_branch", branch),
             lane("parking_right", line(-60, -3.0, 50, -3.0), 2.5, "parking")]
    objects = [obj(1, "vehicle.car", track_along(branch, 85, 7), "red"),
               obj(2, "vehicle.truck", track_along(east, 100, 6), "green"),
               obj(3, "vehicle.motorcycle", track_along(east, 45, 6), "black"),
               obj(4, "vehicle.car", static(5, -3.0), "white"), obj(5, "vehicle.car", static(30, -3.0), "blue", SIZES["suv"]),
               obj(6, "vehicle.car", track_along(branch, 30, 6), "silver"),
               obj(7, "vehicle.bus.rigid", track_along(east, 190, 8), "yellow")]
    write("blind-fork", "hand-made layout: a one-way road whose left lane forks off to the north-east", lanes, east, 5,
          objects)


def zebra():
    """A two-way street (ego east, y=0; west y=3.5) with a zebra crossing at x=30, a cycle lane on the
    right (y=-2.25) and a bus stop bay (x 42-62, y=-3.25) interrupting it, parking on the left
    (y=6.25). Written for set v20."""
    west = line(220, 3.5, -60, 3.5)
    lanes = [lane("east", line(-60, 0, 220, 0)), lane("west", west),
             lane("cycle_lane_a", line(-60, -2.25, 40, -2.25), 1.5), lane("cycle_lane_b", line(64, -2.25, 220, -2.25), 1.5),
             lane("bus_stop_bay", line(42, -3.25, 62, -3.25), 3.0, "parking"),
             lane("parking_left", line(220, 6.25, -60, 6.25), 2.5, "parking")]
    objects = [obj(1, "vehicle.bus.rigid", static(52, -3.25), "red"),
               obj(2, "vehicle.bicycle", track_along(line(-60, -2.25, 40, -2.25), 65, 2.5), "blue"),
               obj(3, "human.pedestrian.adult", track_along(line(30, -5, 30, 9), 0, 1.2)),
               obj(4, "human.pedestrian.adult", track_along(line(29, 9, 29, -5), 2, 1.0)),
               obj(5, "vehicle.car", static(22, 0.0), "black"),
               obj(6, "vehicle.car", track_along(west, 100, 8), "white"),
               obj(7, "vehicle.car", static(10, 6.25, math.pi), "silver"), obj(8, "vehicle.car", static(40, 6.25, math.pi), "green"),
               obj(9, "vehicle.car", static(75, 6.25, math.pi), "yellow"),
               obj(10, "vehicle.car", track_along(line(-60, 0, 220, 0), 40, 1.5), "orange")]
    write("blind-zebra", "hand-made layout: a two-way street with a zebra crossing, a cycle lane and a bus stop bay",
          lanes, line(-60, 0, 220, 0), 1.0, objects)


def main():
    motorway()
    one_way_grid()
    lane_drop()
    fork()
    zebra()


if __name__ == "__main__":
    main()
