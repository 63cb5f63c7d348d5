"""Reading and validating what comes in: the IR, scenes, actuator modes, the repository layout, random robots for tests."""
