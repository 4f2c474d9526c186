"""The brushless DC motor lead-screw actuator: catalog actuators and designs from parts."""
