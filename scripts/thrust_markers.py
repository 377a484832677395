#!/usr/bin/python3
"""Draws thrusters' thrusts for rviz: one arrow per actuator of a body's
`actuator_states` (sensor_msgs/JointState, effort = thrust T [N]), from
the origin of the actuator's TF frame along its +z axis, T * ~scale long,
stamped as the state.

Parameters:
  ~actuator_states  the topic to draw (default: actuator_states)
  ~frames           actuator name -> TF frame (default: each actuator's own
                    name, as for a URDF body's rotor links)
  ~scale            arrow length per newton [m/N] (default 0.05)
Publishes ~markers (visualization_msgs/MarkerArray).
"""
import rospy
from geometry_msgs.msg import Point
from sensor_msgs.msg import JointState
from visualization_msgs.msg import Marker, MarkerArray


class ThrustMarkers(object):
    def __init__(self):
        self.frames = rospy.get_param('~frames', {})
        self.scale = float(rospy.get_param('~scale', 0.05))
        self.markers = rospy.Publisher('~markers', MarkerArray, queue_size=10)
        self.states = rospy.Subscriber(rospy.get_param('~actuator_states', 'actuator_states'),
                                       JointState, self.on_states, queue_size=10)

    def on_states(self, msg):
        out = MarkerArray()
        for k, (name, thrust) in enumerate(zip(msg.name, msg.effort)):
            marker = Marker()
            marker.header.stamp = msg.header.stamp
            marker.header.frame_id = self.frames.get(name, name)
            marker.ns = 'thrust'
            marker.id = k
            marker.type = Marker.ARROW
            marker.action = Marker.ADD
            marker.pose.orientation.w = 1.0
            marker.points = [Point(0.0, 0.0, 0.0), Point(0.0, 0.0, thrust * self.scale)]
            marker.scale.x = 0.015  # shaft diameter [m]
            marker.scale.y = 0.03   # head diameter [m]
            marker.scale.z = 0.04   # head length [m]
            marker.color.r, marker.color.g, marker.color.b, marker.color.a = 1.0, 0.5, 0.0, 1.0
            out.markers.append(marker)
        self.markers.publish(out)


if __name__ == '__main__':
    rospy.init_node('thrust_markers')
    ThrustMarkers()
    rospy.spin()
