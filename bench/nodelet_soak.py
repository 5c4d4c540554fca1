#!/usr/bin/env python3
"""Driver of the nodelet soak (bench/nodelet_soak.sh starts bench/nodelet_soak.launch, then this).

In sim time, until --duration-s: waits for Text AMCL's global localization to converge on the truth, then
repeats a cycle of faults, each step waiting on a condition (with a timeout), never a fixed sleep:
  1. kidnap: teleports the simulated robot (~teleport, the localizer is not told) >= 8 m along the corridor;
     recovered when 3 amcl_pose in a row are within --recover-m and --recover-deg of the ground truth;
     the truth's travel from the teleport to recovery is recorded;
  2. bad messages on the live topics: a scan of NaN / +inf / -inf beams, a scan of 10 ranges whose angles say
     360, a detection array with a 1 MB text, and set_map with an all-occupied 100 x 100 map; each must leave
     the localizer tracking the truth (the next amcl_pose within --recover-m) and set_map must answer
     success false; what the nodes said about each (/rosout) is recorded;
  3. map swap: set_map with the good map (the latched /map) and the true pose; must answer success true and
     the next amcl_pose must be near the truth.
Throughout: the resident memory (VmRSS) of the given processes every --rss-every-s wall seconds; "stale
state": /amcl/state saying converged or tracking while the truth drove --stale-m without a new amcl_pose;
/diagnostics of both nodelets (level, message, map in force, scans dropped, last error; the mapper's back-end
nodes, those on mapped ground and its last solve's seconds) at every step. Writes DIR/rss.csv,
DIR/events.csv, DIR/summary.json and prints a summary; exits 1 if a check failed.
"""
import argparse
import csv
import json
import math
import os
import random
import sys
import threading
import time

import genpy.dynamic
import rospy
from geometry_msgs.msg import Pose2D, PoseWithCovarianceStamped
from nav_msgs.msg import OccupancyGrid, Odometry
from nav_msgs.srv import SetMap, SetMapRequest
from rosgraph_msgs.msg import Log
from sensor_msgs.msg import LaserScan
from std_msgs.msg import String

from doorplate_localization.msg import TextDetection, TextDetectionArray


def yaw_of(q):
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def angle_diff(a, b):
    return abs(math.atan2(math.sin(a - b), math.cos(a - b)))


def rss_kb(pid):
    try:
        with open("/proc/%d/status" % pid) as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
    except OSError:
        return None
    return None


class Soak:
    def __init__(self, args):
        self.args = args
        self.lock = threading.Lock()
        self.truth = None  # (t, x, y, yaw)
        self.truth_path_m = 0.0  # distance the truth has driven since the start
        self.estimates = []  # (sim t, x, y, yaw, error m, yaw error rad, truth path m) since the last reset
        self.last_estimate_path_m = 0.0
        self.state = ""
        self.state_changes = []
        self.stale = []  # [sim t, state, metres driven without an estimate] per stretch
        self.in_stale = False
        self.diagnostics = {}  # name -> (level, message, {key: value})
        self.rosout = []  # (sim t, node, level, text) of warnings and errors
        self.good_map = None
        self.events = []
        self.failures = []
        self.rss = []
        self.rss_start_index = 0  # the first sample after global localization (maps and OCR models loaded)
        rospy.Subscriber("/base_pose_ground_truth", Odometry, self.on_truth, queue_size=50)
        rospy.Subscriber("/amcl_pose", PoseWithCovarianceStamped, self.on_estimate, queue_size=20)
        rospy.Subscriber("/amcl/state", String, self.on_state, queue_size=10)
        rospy.Subscriber("/diagnostics", rospy.AnyMsg, self.on_diagnostics, queue_size=20)
        rospy.Subscriber("/rosout_agg", Log, self.on_rosout, queue_size=200)
        rospy.Subscriber("/map", OccupancyGrid, self.on_map, queue_size=1)
        self.scan_pub = rospy.Publisher("/scan", LaserScan, queue_size=5)
        self.detections_pub = rospy.Publisher("/text_detections", TextDetectionArray, queue_size=2)
        self.teleport_pub = rospy.Publisher("/corridor_sim/teleport", Pose2D, queue_size=1, latch=False)
        self.diag_class = None

    # ---- callbacks ----
    def on_truth(self, msg):
        p = msg.pose.pose
        with self.lock:
            now = msg.header.stamp.to_sec()
            if self.truth is not None:
                step = math.hypot(p.position.x - self.truth[1], p.position.y - self.truth[2])
                if step < 1.0:  # a teleport is no travel
                    self.truth_path_m += step
            self.truth = (now, p.position.x, p.position.y, yaw_of(p.orientation))
            without_m = self.truth_path_m - self.last_estimate_path_m
            if self.state in ("converged", "tracking") and without_m > self.args.stale_m:
                if not self.in_stale:  # one record per stretch, with its longest distance
                    self.stale.append([now, self.state, without_m])
                    self.in_stale = True
                self.stale[-1][2] = without_m

    def on_estimate(self, msg):
        p = msg.pose.pose
        with self.lock:
            if self.truth is None:
                return
            _, tx, ty, tyaw = self.truth
            x, y, yaw = p.position.x, p.position.y, yaw_of(p.orientation)
            self.estimates.append((msg.header.stamp.to_sec(), x, y, yaw, math.hypot(x - tx, y - ty),
                                   angle_diff(yaw, tyaw), self.truth_path_m))
            self.last_estimate_path_m = self.truth_path_m
            self.in_stale = False

    def on_state(self, msg):
        with self.lock:
            if msg.data != self.state:
                self.state_changes.append((rospy.get_time(), msg.data))
            if self.state not in ("converged", "tracking"):
                self.last_estimate_path_m = self.truth_path_m  # distance without an estimate counts from here
            self.state = msg.data

    def on_diagnostics(self, raw):
        if self.diag_class is None:
            header = raw._connection_header
            classes = genpy.dynamic.generate_dynamic(header["type"], header["message_definition"])
            self.diag_class = classes[header["type"]]
        msg = self.diag_class()
        msg.deserialize(raw._buff)
        with self.lock:
            for s in msg.status:
                self.diagnostics[s.name] = (ord(s.level) if isinstance(s.level, bytes) else s.level, s.message,
                                            {v.key: v.value for v in s.values})

    def on_rosout(self, msg):
        if msg.level >= Log.WARN:
            with self.lock:
                self.rosout.append((rospy.get_time(), msg.name, msg.level, msg.msg[:300]))

    def on_map(self, msg):
        if self.good_map is None:
            self.good_map = msg

    # ---- conditions ----
    def wait_for(self, what, condition, timeout_s):
        """Waits (sim time) until condition() is true; False after timeout_s sim seconds."""
        start = rospy.get_time()
        while not rospy.is_shutdown():
            with self.lock:
                if condition():
                    return True
            if rospy.get_time() - start > timeout_s:
                self.failures.append("%s: not within %.0f s" % (what, timeout_s))
                return False
            time.sleep(0.05)
        return False

    def on_truth_in_a_row(self, n, since_index):
        recent = self.estimates[since_index:]
        if len(recent) < n:
            return False
        return all(e[4] <= self.args.recover_m and math.degrees(e[5]) <= self.args.recover_deg for e in recent[-n:])

    def diag_snapshot(self):
        with self.lock:
            return {name: [level, message, values.get("map in force", ""), values.get("scans dropped", ""),
                           values.get("last error", values.get("error", "")), values.get("back-end nodes", ""),
                           values.get("nodes on mapped ground (scan not kept)", ""), values.get("last solve (s)", "")]
                    for name, (level, message, values) in self.diagnostics.items()}

    def record(self, kind, **fields):
        fields.update(kind=kind, sim_t=round(rospy.get_time(), 1), state=self.state, diagnostics=self.diag_snapshot())
        self.events.append(fields)
        print("[soak] %7.1f s %s: %s" % (fields["sim_t"], kind,
              json.dumps({k: v for k, v in fields.items() if k not in ("kind", "sim_t", "diagnostics")})), flush=True)

    def said_since(self, t0, needle):
        with self.lock:
            return [r for r in self.rosout if r[0] >= t0 - 0.5 and needle in r[3]][:3]

    # ---- steps ----
    def localized(self, what, timeout_s):
        with self.lock:
            start_index, start_path, t0 = len(self.estimates), self.truth_path_m, rospy.get_time()
        ok = self.wait_for(what, lambda: self.on_truth_in_a_row(3, start_index), timeout_s)
        with self.lock:
            worst = max([e[4] for e in self.estimates[start_index:]], default=float("nan"))
            travel = self.truth_path_m - start_path
        return ok, travel, rospy.get_time() - t0, worst

    def kidnap(self, rng):
        with self.lock:
            _, x, y, yaw = self.truth
        while True:
            nx = rng.uniform(self.args.x_min, self.args.x_max)
            if abs(nx - x) >= 8.0:
                break
        target = Pose2D(x=nx, y=rng.uniform(self.args.y_min, self.args.y_max), theta=rng.choice([0.0, math.pi]))
        with self.lock:
            self.estimates.clear()
        t0 = rospy.get_time()
        self.teleport_pub.publish(target)
        moved = self.wait_for("kidnap: the simulator moved the robot",
                              lambda: self.truth[0] > t0 and math.hypot(self.truth[1] - target.x, self.truth[2] - target.y) < 0.5,
                              30.0)
        ok, travel, took, worst = self.localized("kidnap recovery", self.args.recover_timeout_s) if moved else (False, 0, 0, 0)
        self.record("kidnap", moved_m=round(math.hypot(target.x - x, target.y - y), 1), recovered=ok,
                    travel_to_recovery_m=round(travel, 1), sim_s_to_recovery=round(took, 1),
                    max_error_m=round(worst, 1))

    def scan(self, ranges, angle_min, angle_max, increment):
        s = LaserScan()
        s.header.stamp = rospy.Time.now()
        s.header.frame_id = "laser"
        s.angle_min, s.angle_max, s.angle_increment = angle_min, angle_max, increment
        s.range_min, s.range_max = 0.05, 30.0
        s.ranges = ranges
        return s

    def still_tracking(self, kind, t0, needle, **extra):
        with self.lock:
            start_index = len(self.estimates)
        ok = self.wait_for(kind + ": the localizer goes on tracking the truth",
                           lambda: self.on_truth_in_a_row(2, start_index), self.args.recover_timeout_s)
        said = self.said_since(t0, needle)
        self.record(kind, tracking_after=ok, said=[("%s: %s" % (r[1], r[3][:220])) for r in said], **extra)

    def bad_messages(self):
        n = 360
        t0 = rospy.get_time()
        ranges = [float("nan"), float("inf"), float("-inf")] * (n // 3)
        for _ in range(3):
            self.scan_pub.publish(self.scan(ranges, -math.pi, math.pi - 2 * math.pi / n, 2 * math.pi / n))
        self.still_tracking("bad_scan_nan_inf", t0, "/scan")
        t0 = rospy.get_time()
        for _ in range(3):
            self.scan_pub.publish(self.scan([2.0] * 10, -math.pi, math.pi - 2 * math.pi / n, 2 * math.pi / n))
        self.still_tracking("bad_scan_10_ranges_say_360", t0, "make 360 beams")
        t0 = rospy.get_time()
        array = TextDetectionArray()
        array.header.stamp = rospy.Time.now()
        array.header.frame_id = "camera_optical"
        d = TextDetection()
        d.text = "4" * (1 << 20)
        d.confidence = 0.9
        d.crossed_center = True
        array.detections = [d]
        self.detections_pub.publish(array)
        self.still_tracking("detection_text_1_mb", t0, "1048576 bytes")
        t0 = rospy.get_time()
        grid = OccupancyGrid()
        grid.header.frame_id = "map"
        grid.info.resolution = 0.05
        grid.info.width = grid.info.height = 100
        grid.info.origin.orientation.w = 1.0
        grid.data = [100] * 10000
        req = SetMapRequest(map=grid)
        req.initial_pose.header.frame_id = "map"
        req.initial_pose.pose.pose.orientation.w = 1.0
        res = self.set_map(req)
        if res is None or res.success:
            self.failures.append("set_map all occupied: answered %s, expected success false" % res)
        self.still_tracking("set_map_all_occupied", t0, "set_map", success=None if res is None else res.success)

    def set_map(self, req):
        try:
            return rospy.ServiceProxy("/set_map", SetMap)(req)
        except (rospy.ServiceException, rospy.ROSException) as e:
            self.failures.append("set_map: %s" % e)
            return None

    def map_swap(self):
        with self.lock:
            _, x, y, yaw = self.truth
            self.estimates.clear()
        req = SetMapRequest(map=self.good_map)
        req.initial_pose.header.frame_id = "map"
        req.initial_pose.header.stamp = rospy.Time.now()
        req.initial_pose.pose.pose.position.x, req.initial_pose.pose.pose.position.y = x, y
        req.initial_pose.pose.pose.orientation.z, req.initial_pose.pose.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
        cov = [0.0] * 36
        cov[0] = cov[7] = 0.25 ** 2
        cov[35] = math.radians(10) ** 2
        req.initial_pose.pose.covariance = cov
        res = self.set_map(req)
        if res is None or not res.success:
            self.failures.append("set_map good map: answered %s, expected success true" % res)
        ok, travel, took, worst = self.localized("map swap: tracking the truth on the new map", self.args.recover_timeout_s)
        self.record("map_swap", success=None if res is None else res.success, tracking_after=ok,
                    sim_s_to_track=round(took, 1))

    def sample_rss(self, pids, stop):
        start = time.time()
        while not stop.is_set():
            row = {"wall_s": round(time.time() - start, 1), "sim_s": round(rospy.get_time(), 1)}
            for name, pid in pids.items():
                row[name] = rss_kb(pid)
            self.rss.append(row)
            stop.wait(self.args.rss_every_s)

    def run(self, pids):
        rng = random.Random(self.args.seed)
        stop = threading.Event()
        sampler = threading.Thread(target=self.sample_rss, args=(pids, stop), daemon=True)
        sampler.start()
        if not self.wait_for("the first ground-truth pose and the latched map",
                             lambda: self.truth is not None and self.good_map is not None, 120.0):
            return self.finish(stop)
        t_start = rospy.get_time()
        ok, travel, took, worst = self.localized("global localization", self.args.recover_timeout_s)
        self.rss_start_index = len(self.rss)
        self.record("global_localization", recovered=ok, travel_to_recovery_m=round(travel, 1),
                    sim_s_to_recovery=round(took, 1))
        cycle = 0
        while not rospy.is_shutdown() and rospy.get_time() - t_start < self.args.duration_s:
            cycle += 1
            self.kidnap(rng)
            self.bad_messages()
            self.map_swap()
            next_cycle = rospy.get_time() + self.args.cycle_s
            while not rospy.is_shutdown() and rospy.get_time() < min(next_cycle, t_start + self.args.duration_s):
                time.sleep(0.5)  # the patrol goes on between cycles; nothing is checked by this wait
        self.record("end", cycles=cycle, sim_s=round(rospy.get_time() - t_start, 1))
        return self.finish(stop)

    def finish(self, stop):
        stop.set()
        out = self.args.out
        os.makedirs(out, exist_ok=True)
        if self.rss:
            with open(os.path.join(out, "rss.csv"), "w", newline="") as f:
                w = csv.DictWriter(f, fieldnames=list(self.rss[0].keys()))
                w.writeheader()
                w.writerows(self.rss)
        with open(os.path.join(out, "events.json"), "w") as f:
            json.dump(self.events, f, indent=1)
        stale = [[round(s[0], 1), s[1], round(s[2], 1)] for s in self.stale]
        summary = {"failures": self.failures, "stale_state": stale, "state_changes": len(self.state_changes),
                   "rss_kb": {}}
        for name in (self.rss[0].keys() if self.rss else []):
            if name in ("wall_s", "sim_s"):
                continue
            values = [r[name] for r in self.rss[self.rss_start_index:] if r[name] is not None]
            if values:
                summary["rss_kb"][name] = {"start": values[0], "end": values[-1], "max": max(values),
                                           "at_launch": self.rss[0][name], "samples": len(values)}
        if stale:
            self.failures.append("stale state: %d stretches where the state said converged/tracking and the robot "
                                 "drove %.1f m without an estimate" % (len(stale), self.args.stale_m))
        for name, s in summary["rss_kb"].items():
            if s["end"] - s["start"] > self.args.rss_growth_kb:
                self.failures.append("%s: RSS grew %d kB (start %d, end %d), more than %d" % (
                    name, s["end"] - s["start"], s["start"], s["end"], self.args.rss_growth_kb))
        with open(os.path.join(out, "summary.json"), "w") as f:
            json.dump(summary, f, indent=1)
        print("[soak] summary: " + json.dumps(summary), flush=True)
        for f in self.failures:
            print("[soak] FAILED: " + f, flush=True)
        return 1 if self.failures else 0


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--duration-s", type=float, default=3600.0, help="simulated seconds after global localization")
    p.add_argument("--cycle-s", type=float, default=300.0, help="simulated seconds between fault cycles")
    p.add_argument("--recover-m", type=float, default=0.5)
    p.add_argument("--recover-deg", type=float, default=15.0)
    p.add_argument("--recover-timeout-s", type=float, default=300.0)
    p.add_argument("--stale-m", type=float, default=2.0)
    p.add_argument("--rss-every-s", type=float, default=10.0, help="wall seconds")
    p.add_argument("--rss-growth-kb", type=int, default=50000)
    p.add_argument("--pid", action="append", default=[], help="NAME=PID of a process whose RSS is sampled")
    p.add_argument("--x-min", type=float, default=3.0)
    p.add_argument("--x-max", type=float, default=40.5)
    p.add_argument("--y-min", type=float, default=0.6)
    p.add_argument("--y-max", type=float, default=1.25)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--out", required=True)
    args = p.parse_args(rospy.myargv()[1:])
    rospy.init_node("nodelet_soak", anonymous=False)
    pids = {k: int(v) for k, v in (x.split("=", 1) for x in args.pid)}
    sys.exit(Soak(args).run(pids))


if __name__ == "__main__":
    main()
