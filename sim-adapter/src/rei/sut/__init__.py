"""The system under test: controllers that drive the robot (reference navigation, scripts, user plug-ins)."""
