"""REI - Robotic Event Interceptor: simulate, monitor and judge mobile-robot missions."""

__version__ = "0.1.0"
