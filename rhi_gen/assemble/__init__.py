"""Assemble: a VendorConfig and a UrdfRobot cross-checked into the RobotModel the templates read.

Its own stage (above the model and the transports, below rendering) because deciding a joint's
command interfaces asks the robot's transport, and the model itself must not know any transport.
"""
