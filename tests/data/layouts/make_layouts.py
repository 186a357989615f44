#!/usr/bin/env python3
"""Writes the layout-only scenes of the blind command sets (tests/data/commands-blind-v*.jsonl).

They differ from the dev layout on purpose: a one-way three-lane street with parking on both sides
and side streets on both sides; a two-lane road that curves left, with a bus bay and a side street
to the left; a divided road, three lanes each way, a crossroads at 50 m, parking on the right; a
T junction (v3); an undivided avenue, two lanes each way, parking both sides, staggered side
streets left and right (v6); a road bending right with kerbside parking on the left and a side
street to the right (v7); a wide crossroads, two lanes each way on both roads, the ego in the
inner lane (v8); a narrow residential street, parked cars on both sides, a side street to the right
(v9); a dual carriageway with an on-ramp merging from the right (v10); a left-hand-traffic road
(as in Singapore or the UK), parking and a side street on the left (v11).
Run from anywhere: python3 tests/data/layouts/make_layouts.py (deterministic, no randomness).
"""
import math

import layouts_v21
import layouts_v23
import layouts_v24
import layouts_v25
import layouts_v26
import layouts_v27
import layouts_v28
import layouts_v29
import layouts_v30
import more_layouts
from layout_lib import SIZES, frange, lane, line, obj, offset, sample, static, track_along, write


def oneway():
    """One-way street, three lanes, parking both sides, side streets right (x=35) and left (x=95)."""
    lanes = [lane("lane_left", line(-60, 3.5, 220, 3.5)), lane("lane_middle", line(-60, 0, 220, 0)),
             lane("lane_right", line(-60, -3.5, 220, -3.5)),
             lane("parking_right_a", line(-60, -6.5, 28, -6.5), 2.5, "parking"),
             lane("parking_right_b", line(42, -6.5, 220, -6.5), 2.5, "parking"),
             lane("parking_left_a", line(-60, 6.5, 88, 6.5), 2.5, "parking"),
             lane("parking_left_b", line(102, 6.5, 220, 6.5), 2.5, "parking"),
             lane("side_right_south", line(33.25, -7.75, 33.25, -80)), lane("side_right_north", line(36.75, -80, 36.75, -7.75)),
             lane("side_left_north", line(96.75, 7.75, 96.75, 80)), lane("side_left_south", line(93.25, 80, 93.25, 7.75))]
    mid = line(-60, 0, 220, 0)
    left, right = line(-60, 3.5, 220, 3.5), line(-60, -3.5, 220, -3.5)
    objects = [obj(1, "vehicle.car", static(12, -6.5), "red"), obj(2, "vehicle.car", static(50, -6.5), "silver"),
               obj(3, "vehicle.car", track_along(left, 80, 9), "blue"), obj(4, "vehicle.truck", track_along(right, 90, 5), "white"),
               obj(5, "vehicle.car", track_along(mid, 46, 7), "black", SIZES["suv"]),
               obj(6, "vehicle.motorcycle", track_along(left, 40, 10), "orange"),
               obj(7, "vehicle.car", static(25, 6.5), "green"), obj(8, "vehicle.bus.rigid", track_along(right, 135, 6), "yellow"),
               obj(9, "human.pedestrian.adult", track_along(line(-60, -9, 220, -9), 68, 1.3)),
               obj(10, "vehicle.bicycle", track_along(right, 30, 5), "black"),
               obj(11, "movable_object.trafficcone", static(40, -5.2), "orange")]
    write("blind-oneway", "hand-made layout: one-way street, three lanes, parking both sides, side streets right and left",
          lanes, mid, 7, objects)


def curve_pts(x_start, y_offset, radius=150.0, degrees=60.0, x_from=-60.0, step=5.0):
    """A road along +x that bends left at x_start (centre of the bend on the left); y_offset: lane offset."""
    pts = [[x, y_offset, 0.0] for x in frange(x_from, x_start, step)]
    r = radius - y_offset
    n = int(math.radians(degrees) * radius / step)
    for k in range(1, n + 1):
        a = math.radians(degrees) * k / n
        pts.append([x_start + r * math.sin(a), radius - r * math.cos(a), 0.0])
    return pts


def curve():
    """Two-lane road (one each way) bending left from x=30, bus bay on the right, side street left at x=18."""
    ego = curve_pts(30, 0)
    oncoming = list(reversed(curve_pts(30, 3.5)))
    lanes = [lane("eastbound", ego), lane("westbound", oncoming),
             lane("bus_bay", line(-5, -3.25, 25, -3.25), 3.0, "parking"),
             lane("side_north", line(19.75, 5.25, 19.75, 80)), lane("side_south", line(16.25, 80, 16.25, 5.25))]
    length = sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(oncoming, oncoming[1:]))
    objects = [obj(1, "vehicle.bus.rigid", static(12, -3.25), "white"),
               obj(2, "vehicle.car", track_along(ego, 90, 7), "grey"),
               obj(3, "vehicle.car", track_along(oncoming, length - 121, 10), "red"),
               obj(4, "vehicle.truck", track_along(oncoming, length - 172, 8), "blue"),
               obj(5, "vehicle.motorcycle", track_along(ego, 48, 9), "black"),
               obj(6, "vehicle.car", static(16.25, 11, -math.pi / 2), "yellow"),
               obj(7, "human.pedestrian.adult", static(10, -6)),
               obj(8, "human.pedestrian.adult", track_along(line(60, 6, -60, 6), 55, 1.4)),
               obj(9, "vehicle.car", track_along(oncoming, length - 30, 11), "white")]
    write("blind-curve", "hand-made layout: two-lane road bending left, bus bay right, side street left",
          lanes, ego, 9, objects)


def divided():
    """Divided road, three lanes each way (ego in the right lane), crossroads at x=50, parking right to x=30."""
    lanes = [lane("east_right", line(-60, 0, 220, 0)), lane("east_middle", line(-60, 3.5, 220, 3.5)),
             lane("east_left", line(-60, 7, 220, 7)),
             lane("west_left", line(220, 13, -60, 13)), lane("west_middle", line(220, 16.5, -60, 16.5)),
             lane("west_right", line(220, 20, -60, 20)),
             lane("parking_right", line(-60, -3, 30, -3), 2.5, "parking"),
             lane("cross_north", line(51.75, -60, 51.75, 80)), lane("cross_south", line(48.25, 80, 48.25, -60))]
    east = lambda y: line(-60, y, 220, y)
    west = lambda y: line(220, y, -60, y)
    objects = [obj(1, "vehicle.car", track_along(east(3.5), 85, 12), "white"),
               obj(2, "vehicle.car", track_along(east(7), 50, 15), "red"),
               obj(3, "vehicle.truck", track_along(east(0), 100, 10), "grey"),
               obj(4, "vehicle.car", static(10, -3), "black"), obj(5, "vehicle.car", static(-5, -3), "blue"),
               obj(6, "vehicle.car", track_along(west(13), 150, 14), "silver"),
               obj(7, "vehicle.bus.rigid", track_along(west(20), 190, 8), "red"),
               obj(8, "vehicle.car", static(48.25, 24, -math.pi / 2), "green"),
               obj(9, "vehicle.emergency.police", static(22, -3), "white"),
               obj(10, "movable_object.trafficcone", static(35, -3), "orange"),
               obj(11, "human.pedestrian.adult", static(46, -6))]
    write("blind-divided", "hand-made layout: divided road, three lanes each way, crossroads, parking right",
          lanes, east(0), 12, objects)


def tee():
    """Two-lane road (one each way) ending at a T junction at x=75: the cross road runs north-south."""
    east, west = line(-60, 0, 71, 0), line(71, 3.5, -60, 3.5)
    lanes = [lane("east", east), lane("west", west),
             lane("cross_south", line(73.25, 90, 73.25, -90)), lane("cross_north", line(76.75, -90, 76.75, 90)),
             lane("parking_left", line(-60, 6.5, 60, 6.5), 2.5, "parking")]
    objects = [obj(1, "vehicle.car", track_along(east, 85, 6), "white"),
               obj(2, "vehicle.car", track_along(west, 40, 9), "black"),
               obj(3, "vehicle.truck", track_along(line(76.75, -90, 76.75, 90), 60, 7), "orange"),
               obj(4, "vehicle.car", static(15, 6.5), "blue"), obj(5, "vehicle.car", static(35, 6.5), "red"),
               obj(6, "vehicle.motorcycle", track_along(east, 40, 8), "green"),
               obj(7, "human.pedestrian.adult", static(20, -4))]
    write("blind-tee", "hand-made layout: two-lane road ending at a T junction, parking on the left",
          lanes, east, 6, objects)


def avenue():
    """Undivided avenue, two lanes each way (ego in the right one), parking on both sides, a side street
    left at x=45 and one right at x=110."""
    east = lambda y: line(-60, y, 220, y)
    west = lambda y: line(220, y, -60, y)
    lanes = [lane("east_kerb", east(0)), lane("east_inner", east(3.5)),
             lane("west_inner", west(7)), lane("west_kerb", west(10.5)),
             lane("parking_right_a", line(-60, -3, 100, -3), 2.5, "parking"),
             lane("parking_right_b", line(120, -3, 220, -3), 2.5, "parking"),
             lane("parking_left_a", line(220, 13.5, 55, 13.5), 2.5, "parking"),
             lane("parking_left_b", line(35, 13.5, -60, 13.5), 2.5, "parking"),
             lane("side_left_north", line(46.75, 12.25, 46.75, 90)), lane("side_left_south", line(43.25, 90, 43.25, 12.25)),
             lane("side_right_south", line(108.25, -1.75, 108.25, -90)),
             lane("side_right_north", line(111.75, -90, 111.75, -1.75))]
    objects = [obj(1, "vehicle.car", static(20, -3), "red"), obj(2, "vehicle.car", static(32, -3), "silver"),
               obj(3, "vehicle.car", static(62, -3), "black"),
               obj(4, "vehicle.car", track_along(east(0), 100, 8), "white"),
               obj(5, "vehicle.truck", track_along(east(3.5), 130, 6), "grey"),
               obj(6, "vehicle.car", track_along(west(7), 100, 10), "blue"),
               obj(7, "vehicle.bus.rigid", track_along(west(10.5), 60, 7), "yellow"),
               obj(8, "vehicle.car", static(43.25, 22, -math.pi / 2), "green"),
               obj(9, "vehicle.motorcycle", track_along(east(3.5), 35, 12), "red"),
               obj(10, "human.pedestrian.adult", static(30, 16)),
               obj(11, "movable_object.trafficcone", static(75, -3), "orange"),
               obj(12, "vehicle.car", static(25, 13.5, math.pi), "white")]
    write("blind-avenue", "hand-made layout: undivided avenue, two lanes each way, parking both sides, "
          "staggered side streets", lanes, east(0), 8, objects)


def right_bend_pts(x_start, y_offset, radius=120.0, degrees=50.0, x_from=-60.0, step=5.0):
    """A road along +x that bends right at x_start (centre of the bend on the right); y_offset: lane offset."""
    pts = [[x, y_offset, 0.0] for x in frange(x_from, x_start, step)]
    r = radius + y_offset
    n = int(math.radians(degrees) * radius / step)
    for k in range(1, n + 1):
        a = math.radians(degrees) * k / n
        pts.append([x_start + r * math.sin(a), -radius + r * math.cos(a), 0.0])
    return pts


def right_bend():
    """Two-lane road (one each way) bending right from x=40, parking on the left to x=30, a side street
    to the right at x=10."""
    ego = right_bend_pts(40, 0)
    oncoming = list(reversed(right_bend_pts(40, 3.5)))
    lanes = [lane("eastbound", ego), lane("westbound", oncoming),
             lane("parking_left", line(30, 6.5, -60, 6.5), 2.5, "parking"),
             lane("side_south", line(11.75, -1.75, 11.75, -80)), lane("side_north", line(8.25, -80, 8.25, -1.75))]
    length = sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(oncoming, oncoming[1:]))
    objects = [obj(1, "vehicle.car", static(0, 6.5, math.pi), "red"),
               obj(2, "vehicle.car", static(20, 6.5, math.pi), "white", SIZES["suv"]),
               obj(3, "vehicle.car", track_along(ego, 90, 8), "silver"),
               obj(4, "vehicle.truck", track_along(oncoming, length - 150, 9), "black"),
               obj(5, "vehicle.car", track_along(oncoming, length - 40, 10), "yellow"),
               obj(6, "vehicle.car", static(8.25, -12, math.pi / 2), "blue"),
               obj(7, "vehicle.motorcycle", track_along(ego, 45, 9), "green"),
               obj(8, "human.pedestrian.adult", static(25, -6)),
               obj(9, "movable_object.trafficcone", static(28, 6.5), "orange"),
               obj(10, "vehicle.emergency.police", static(-10, 6.5, math.pi), "white")]
    write("blind-rightbend", "hand-made layout: two-lane road bending right, parking left, side street right",
          lanes, ego, 7, objects)


def crossroads():
    """Two lanes each way (ego in the inner lane, y=3.5), a crossroads at x=40 with a road of two lanes
    each way across, no parking; a bus stop bay on the right after the junction."""
    east = lambda y: line(-60, y, 220, y)
    west = lambda y: line(220, y, -60, y)
    north = lambda x: line(x, -90, x, 90)
    south = lambda x: line(x, 90, x, -90)
    lanes = [lane("east_kerb", east(0)), lane("east_inner", east(3.5)), lane("west_inner", west(7)),
             lane("west_kerb", west(10.5)), lane("north_kerb", north(47)), lane("north_inner", north(43.5)),
             lane("south_inner", south(40)), lane("south_kerb", south(36.5)),
             lane("bus_stop", line(60, -3, 90, -3), 3.0, "parking")]
    objects = [obj(1, "vehicle.car", track_along(east(3.5), 85, 8), "blue"),
               obj(2, "vehicle.car", track_along(east(0), 70, 8), "white", SIZES["suv"]),
               obj(3, "vehicle.bus.rigid", static(75, -3), "green"),
               obj(4, "vehicle.car", track_along(west(7), 90, 11), "black"),
               obj(5, "vehicle.truck", track_along(west(10.5), 130, 6), "red"),
               obj(6, "vehicle.car", static(40, 20, -math.pi / 2), "silver"),
               obj(7, "vehicle.car", static(47, -15, math.pi / 2), "yellow"),
               obj(8, "vehicle.motorcycle", track_along(east(0), 45, 10), "black"),
               obj(9, "human.pedestrian.adult", track_along(line(33, -12, 33, 20), 0, 1.2)),
               obj(10, "vehicle.car", track_along(east(3.5), 40, 8), "red")]
    write("blind-crossroads", "hand-made layout: wide crossroads, two lanes each way on both roads, ego in the inner lane",
          lanes, east(3.5), 8, objects)


def narrow():
    """A narrow two-way street (3 m lanes, one each way), parking on both sides, a side street to the
    right at x=40; the ego drives slowly."""
    east, west = line(-60, 0, 160, 0), line(160, 3, -60, 3)
    lanes = [lane("east", east, 3.0), lane("west", west, 3.0),
             lane("park_right_a", line(-60, -2.75, 33, -2.75), 2.5, "parking"),
             lane("park_right_b", line(47, -2.75, 160, -2.75), 2.5, "parking"),
             lane("park_left", line(160, 5.75, -60, 5.75), 2.5, "parking"),
             lane("side_out", line(41.5, -1.5, 41.5, -80)), lane("side_in", line(38.5, -80, 38.5, -1.5))]
    objects = [obj(1, "vehicle.car", static(8, -2.75), "grey"), obj(2, "vehicle.car", static(14, -2.75), "white"),
               obj(3, "vehicle.car", static(26, -2.75), "blue", SIZES["suv"]),
               obj(4, "vehicle.car", static(55, -2.75), "red"), obj(5, "vehicle.car", static(5, 5.75, math.pi), "black"),
               obj(6, "vehicle.car", static(30, 5.75, math.pi), "yellow"),
               obj(7, "vehicle.truck", static(62, 5.75, math.pi), "white"),
               obj(8, "vehicle.car", track_along(west, 60, 6), "green"),
               obj(9, "vehicle.bicycle", track_along(east, 80, 4), "orange"),
               obj(10, "human.pedestrian.adult", track_along(line(20, 8, 20, -6), 0, 1.0)),
               obj(11, "vehicle.car", track_along(east, 45, 5), "silver")]
    write("blind-narrow", "hand-made layout: narrow two-way residential street, parking both sides, side street right",
          lanes, east, 5, objects)


def on_ramp():
    """Dual carriageway, two lanes each way behind a 4 m median, an on-ramp joining from the right
    (an acceleration lane from x=20 to x=80); the ego in the right lane."""
    east = lambda y: line(-60, y, 240, y)
    west = lambda y: line(240, y, -60, y)
    ramp = [[-60.0, -20.0, 0.0], [-20.0, -14.0, 0.0], [0.0, -9.0, 0.0], [20.0, -3.5, 0.0]] + line(25, -3.5, 80, -3.5)
    lanes = [lane("east_right", east(0)), lane("east_left", east(3.5)), lane("west_left", west(11)),
             lane("west_right", west(14.5)), lane("on_ramp", ramp)]
    objects = [obj(1, "vehicle.truck", track_along(east(0), 100, 11), "blue"),
               obj(2, "vehicle.car", track_along(east(3.5), 70, 16), "red"),
               obj(3, "vehicle.car", track_along(ramp, 45, 12), "white"),
               obj(4, "vehicle.car", track_along(west(11), 150, 18), "grey"),
               obj(5, "vehicle.bus.rigid", track_along(west(14.5), 120, 12), "white"),
               obj(6, "vehicle.car", track_along(east(0), 35, 15), "black", SIZES["suv"]),
               obj(7, "vehicle.motorcycle", track_along(east(3.5), 20, 20), "yellow"),
               obj(8, "vehicle.car", static(60, -6.0), "silver")]
    write("blind-onramp", "hand-made layout: dual carriageway, two lanes each way, an on-ramp merging from the right",
          lanes, east(0), 14, objects)


def left_hand():
    """Left-hand traffic: the ego drives east in the left lane (y=0), the oncoming lane on its right
    (y=-3.5); parking on the left kerb to x=40, a bus stop bay on the left after it, a side street to
    the left at x=70."""
    east, west = line(-60, 0, 200, 0), line(200, -3.5, -60, -3.5)
    lanes = [lane("eastbound", east), lane("westbound", west),
             lane("parking_left", line(-60, 3, 40, 3), 2.5, "parking"),
             lane("bus_stop", line(45, 3.25, 62, 3.25), 3.0, "parking"),
             lane("side_in", line(71.75, 80, 71.75, 1.75)), lane("side_out", line(68.25, 1.75, 68.25, 80))]
    objects = [obj(1, "vehicle.car", static(10, 3), "white"), obj(2, "vehicle.car", static(24, 3), "black"),
               obj(3, "vehicle.bus.rigid", static(53, 3.25), "red"),
               obj(4, "vehicle.car", track_along(east, 95, 8), "silver"),
               obj(5, "vehicle.car", track_along(west, 110, 10), "blue"),
               obj(6, "vehicle.truck", track_along(west, 40, 7), "yellow"),
               obj(7, "vehicle.motorcycle", track_along(east, 40, 10), "red"),
               obj(8, "vehicle.car", static(71.75, 20, -math.pi / 2), "green"),
               obj(9, "human.pedestrian.adult", static(50, 6))]
    write("blind-lefthand", "hand-made layout: left-hand traffic, parking and a bus stop on the left, side street left",
          lanes, east, 7, objects)


def turn_pocket():
    """Urban arterial: a kerbside bus lane, two through lanes east (ego in the right one, y=0), a
    left-turn pocket opening at x=30 to the crossroads at x=80; two lanes west given as polylines
    along +x with direction "backward"; no parking."""
    east = lambda y: line(-60, y, 220, y)
    west = lambda y: line(220, y, -60, y)
    pocket = [[30.0, 3.5, 0.0], [40.0, 7.0, 0.0]] + line(45, 7, 75, 7)
    backward = lambda lid, y: dict(lane(lid, line(-60, y, 220, y)), direction="backward")
    lanes = [lane("east_bus_lane", east(-3.5)), lane("east_right", east(0)), lane("east_left", east(3.5)),
             lane("east_turn_pocket", pocket), backward("west_inner", 10.5), backward("west_kerb", 14),
             lane("north_out", line(81.75, 16, 81.75, 100)), lane("north_in", line(78.25, 100, 78.25, 16)),
             lane("south_out", line(78.25, -5.25, 78.25, -90)), lane("south_in", line(81.75, -90, 81.75, -5.25))]
    objects = [obj(1, "vehicle.bus.rigid", track_along(east(-3.5), 70, 7), "red"),
               obj(2, "vehicle.car", track_along(east(0), 95, 8), "white"),
               obj(3, "vehicle.car", static(68, 7), "grey"),
               obj(4, "vehicle.car", static(60, 7), "black", SIZES["suv"]),
               obj(5, "vehicle.car", track_along(west(10.5), 100, 12), "blue"),
               obj(6, "vehicle.truck", track_along(west(14), 160, 6), "orange"),
               obj(7, "vehicle.motorcycle", track_along(east(3.5), 65, 12), "yellow"),
               obj(8, "vehicle.car", static(78.25, 25, -math.pi / 2), "silver"),
               obj(9, "human.pedestrian.adult", track_along(line(74, -8, 74, 20), 0, 1.2)),
               obj(10, "vehicle.bicycle", track_along(east(-3.5), 50, 5), "green"),
               obj(11, "vehicle.emergency.police", static(81.75, -20, math.pi / 2), "white"),
               obj(12, "vehicle.car", track_along(east(0), 45, 8), "green")]
    write("blind-turnpocket", "hand-made layout: arterial with a kerbside bus lane, a left-turn pocket before a "
          "crossroads, westbound lanes drawn backward", lanes, east(0), 8, objects)


def s_bend_centre(step=5.0):
    """Road centre along +x from x=-60, straight to x=30, 35 deg left over 60 m, 35 deg right over 60 m, straight."""
    pts, x, y, yaw = [[-60.0, 1.75, 0.0]], -60.0, 1.75, 0.0
    for length, turn in ((90, 0.0), (60, 35.0), (60, -35.0), (120, 0.0)):
        n = int(length / step)
        for _ in range(n):
            yaw += math.radians(turn) / n / 2
            x, y = x + step * math.cos(yaw), y + step * math.sin(yaw)
            yaw += math.radians(turn) / n / 2
            pts.append([round(x, 3), round(y, 3), 0.0])
    return pts


def s_bend():
    """Country road, one lane each way (the oncoming one drawn along +x, direction "backward"),
    an S-bend from x=30, a lay-by on the right, a farm track to the right after the bend; a slow
    tractor ahead of the ego."""
    centre = s_bend_centre()
    ego, oncoming = offset(centre, -1.75), offset(centre, 1.75)
    sx, sy, syaw = sample(centre, 170)
    right = lambda d, side: [sx + side * math.sin(syaw) + d * math.sin(syaw), sy - side * math.cos(syaw) - d * math.cos(syaw)]
    track_out = [right(5.25, -1.75) + [0.0], right(80, -1.75) + [0.0]]
    track_in = [right(80, 1.75) + [0.0], right(5.25, 1.75) + [0.0]]
    lanes = [lane("ego_way", ego), dict(lane("other_way", oncoming), direction="backward"),
             lane("lay_by", line(5, -3.25, 30, -3.25), 3.0, "parking"),
             lane("farm_track_out", line(*track_out[0][:2], *track_out[1][:2])),
             lane("farm_track_in", line(*track_in[0][:2], *track_in[1][:2]))]
    back = list(reversed(oncoming))
    length = sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(back, back[1:]))
    tx, ty = right(20, 1.75)
    objects = [obj(1, "vehicle.construction", track_along(ego, 130, 4), "yellow", [4.5, 2.4, 3.0]),
               obj(2, "vehicle.car", track_along(back, length - 140, 11), "red"),
               obj(3, "vehicle.truck", track_along(back, length - 230, 9), "white"),
               obj(4, "vehicle.car", static(18, -3.25), "silver"),
               obj(5, "vehicle.car", track_along(ego, 40, 9), "blue"),
               obj(6, "vehicle.bicycle", track_along(ego, 95, 5), "orange"),
               obj(7, "human.pedestrian.adult", track_along(line(40, 6, -60, 6), 0, 1.3)),
               obj(8, "vehicle.car", static(round(tx, 3), round(ty, 3), round(syaw + math.pi / 2, 4)), "green"),
               obj(9, "vehicle.car", track_along(back, length - 75, 12), "black", SIZES["suv"])]
    write("blind-sbend", "hand-made layout: country road with an S-bend, a lay-by on the right, a farm track "
          "to the right, oncoming lane drawn backward", lanes, ego, 9, objects)


def lht_exit():
    """Left-hand traffic dual carriageway: eastbound a kerbside bus lane (y=3.5, the left), the ego's
    lane (y=0) and an overtaking lane (y=-3.5); a median; westbound two lanes (y=-11, -14.5). An exit
    slip road leaves from the left at x=60; a two-way service road (direction "both") runs behind a
    verge on the left (y=13) with a car parked on it."""
    east = lambda y: line(-60, y, 240, y)
    west = lambda y: line(240, y, -60, y)
    slip = [[60.0, 3.5, 0.0], [75.0, 5.5, 0.0], [90.0, 9.5, 0.0], [110.0, 17.0, 0.0], [140.0, 30.0, 0.0], [170.0, 43.0, 0.0]]
    lanes = [lane("eb_bus_lane", east(3.5)), lane("eb_lane_1", east(0)), lane("eb_lane_2", east(-3.5)),
             lane("exit_slip", slip), lane("wb_lane_2", west(-11)), lane("wb_lane_1", west(-14.5)),
             dict(lane("service_road", line(-60, 13, 100, 13), 4.0), direction="both")]
    objects = [obj(1, "vehicle.bus.rigid", static(40, 3.5), "red"),
               obj(2, "vehicle.truck", track_along(east(-3.5), 90, 10), "white"),
               obj(3, "vehicle.car", track_along(slip, 5, 9), "blue"),
               obj(4, "vehicle.motorcycle", track_along(east(0), 45, 12), "black"),
               obj(5, "vehicle.car", track_along(west(-11), 130, 14), "silver"),
               obj(6, "vehicle.car", track_along(west(-14.5), 60, 11), "green"),
               obj(7, "vehicle.car", static(20, 13), "yellow", SIZES["suv"]),
               obj(8, "vehicle.bicycle", track_along(line(100, 14.5, -60, 14.5), 70, 4), "orange"),
               obj(9, "vehicle.car", track_along(east(0), 110, 11), "grey"),
               obj(10, "human.pedestrian.adult", static(38, 6.5)),
               obj(11, "vehicle.emergency.police", track_along(east(-3.5), 30, 14), "white")]
    write("blind-lhtexit", "hand-made layout: left-hand traffic dual carriageway, a kerbside bus lane with a bus "
          "at a stop, an exit slip road to the left, a two-way service road behind a verge", lanes, east(0), 11, objects)


def roundabout():
    """A two-way road (one lane each way) into a roundabout centred 90 m ahead (radius 14 m,
    counter-clockwise), with arms north, east and south; no parking."""
    cx, cy, r = 90.0, 1.75, 14.0
    ring = [[round(cx + r * math.cos(math.radians(a)), 3), round(cy + r * math.sin(math.radians(a)), 3), 0.0]
            for a in range(-180, 181, 10)]
    lanes = [lane("west_in", line(-60, 0, 70, 0)), lane("west_out", line(70, 3.5, -60, 3.5)),
             lane("east_in", line(220, 3.5, 110, 3.5)), lane("east_out", line(110, 0, 220, 0)),
             lane("north_in", line(88.25, 120, 88.25, 21.75)), lane("north_out", line(91.75, 21.75, 91.75, 120)),
             lane("south_in", line(91.75, -120, 91.75, -18.25)), lane("south_out", line(88.25, -18.25, 88.25, -120)),
             lane("roundabout", ring)]
    objects = [obj(1, "vehicle.car", track_along(ring, 20, 6), "red"),
               obj(2, "vehicle.truck", track_along(line(220, 3.5, 110, 3.5), 40, 5), "blue"),
               obj(3, "vehicle.bus.rigid", track_along(line(91.75, 21.75, 91.75, 120), 5, 7), "green"),
               obj(4, "vehicle.car", static(88.25, 30, -math.pi / 2), "black"),
               obj(5, "vehicle.bicycle", track_along(line(-60, 0, 70, 0), 45, 4), "yellow"),
               obj(6, "vehicle.car", track_along(line(-60, 0, 70, 0), 90, 4), "white"),
               obj(7, "human.pedestrian.adult", track_along(line(64, -5, 64, 9), 0, 1.0)),
               obj(8, "vehicle.car", track_along(line(70, 3.5, -60, 3.5), 10, 9), "silver"),
               obj(9, "vehicle.motorcycle", track_along(line(91.75, -120, 91.75, -18.25), 50, 5), "orange")]
    write("blind-roundabout", "hand-made layout: a two-way road into a roundabout 90 m ahead with three more arms",
          lanes, line(-60, 0, 70, 0), 5, objects)


if __name__ == "__main__":
    roundabout()
    lht_exit()
    turn_pocket()
    s_bend()
    left_hand()
    on_ramp()
    narrow()
    crossroads()
    right_bend()
    avenue()
    oneway()
    curve()
    divided()
    tee()
    more_layouts.main()
    layouts_v21.main()
    layouts_v23.main()
    layouts_v24.main()
    layouts_v25.main()
    layouts_v26.main()
    layouts_v27.main()
    layouts_v28.main()
    layouts_v29.main()
    layouts_v30.main()
