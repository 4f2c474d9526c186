"""The piezohydraulic actuator: piezo stacks driving a hydraulic amplifier."""
