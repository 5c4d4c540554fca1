#!/usr/bin/env python3
"""Writes the seed bags of fuzz/bag_reader_fuzz.cpp into fuzz/corpus/bag_reader/ with rosbag's own writer:
a mapping run as doorplate_map_bag reads it (scans, tf, tf_static, text detections) and a localization run as
doorplate_mission_report reads it (ground truth, odometry, amcl_pose, text detections, state strings), each
uncompressed and compressed (bz2, lz4) in one chunk, and uncompressed in 1 kB chunks. 17 to 37 kB each (most of it
the message definitions rosbag stores with each connection).
Usage (with the build's environment: source scripts/env.sh BUILD): python3 fuzz/make_bag_corpus.py [OUT_DIR]"""
import math
import os
import sys

import rosbag
import rospy
from doorplate_localization.msg import TextDetection, TextDetectionArray
from geometry_msgs.msg import PoseWithCovarianceStamped, TransformStamped
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan
from std_msgs.msg import String
from tf2_msgs.msg import TFMessage


def stamp(t):
    return rospy.Time.from_sec(10.0 + t)


def transform(t, parent, child, x, yaw=0.0, z=0.0):
    m = TransformStamped()
    m.header.stamp, m.header.frame_id, m.child_frame_id = stamp(t), parent, child
    m.transform.translation.x, m.transform.translation.z = x, z
    m.transform.rotation.z, m.transform.rotation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return m


def scan(t):
    s = LaserScan()
    s.header.stamp, s.header.frame_id = stamp(t), "laser"
    s.angle_min, s.angle_increment = -math.pi / 2, math.pi / 8
    s.angle_max = s.angle_min + 8 * s.angle_increment
    s.range_min, s.range_max = 0.1, 30.0
    s.ranges = [1.0, 1.1, 1.3, 1.8, 30.0, float("inf"), 1.8, 1.3, 1.1]
    return s


def detections(t, text):
    a = TextDetectionArray()
    a.header.stamp, a.header.frame_id = stamp(t), "camera_optical"
    d = TextDetection()
    d.text, d.confidence, d.crossed_center = text, 0.9, True
    a.detections = [d]
    return a


def odometry(t, x, frame):
    o = Odometry()
    o.header.stamp, o.header.frame_id, o.child_frame_id = stamp(t), frame, "base_link"
    o.pose.pose.position.x, o.pose.pose.orientation.w = x, 1.0
    return o


def mapping_run(bag):
    bag.write("/tf_static", TFMessage([transform(0, "base_link", "laser", 0.1, z=0.3),
                                       transform(0, "base_link", "camera", 0.0, yaw=-math.pi / 2)]), stamp(0))
    for i in range(3):
        bag.write("/tf", TFMessage([transform(i, "odom", "base_link", 0.5 * i)]), stamp(i))
        bag.write("/scan", scan(i), stamp(i))
    bag.write("/text_detections", detections(1.5, "207"), stamp(1.5))


def localization_run(bag):
    for i in range(3):
        bag.write("/base_pose_ground_truth", odometry(i, 1.0 + 0.5 * i, "world"), stamp(i))
        bag.write("odom", odometry(i, 0.5 * i, "odom"), stamp(i))
        p = PoseWithCovarianceStamped()
        p.header.stamp, p.header.frame_id = stamp(i), "map"
        p.pose.pose.position.x, p.pose.pose.orientation.w = 1.1 + 0.5 * i, 1.0
        bag.write("/amcl_pose", p, stamp(i))
    bag.write("/text_detections", detections(1.5, "214"), stamp(1.5))
    bag.write("/amcl/state", String("converged"), stamp(1.8))
    bag.write("/go_to_room/status", String("arrived: room 214"), stamp(2.0))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "bag_reader")
    os.makedirs(out, exist_ok=True)
    for name, write in (("mapping_run", mapping_run), ("localization_run", localization_run)):
        # One chunk each (rosbag's default threshold); one uncompressed bag in 1 kB chunks (several chunks).
        for compression, chunk_bytes in (("none", 768 * 1024), ("bz2", 768 * 1024), ("lz4", 768 * 1024), ("none", 1024)):
            path = os.path.join(out, "%s_%s%s.bag" % (name, compression, "_small_chunks" if chunk_bytes == 1024 else ""))
            with rosbag.Bag(path, "w", compression=compression, chunk_threshold=chunk_bytes) as bag:
                write(bag)
            print("%s: %d bytes" % (path, os.path.getsize(path)))


if __name__ == "__main__":
    main()
