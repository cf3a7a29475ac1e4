"""alightsize simulator: leg kinematics and (later) landing dynamics. Never imports alightsize."""
