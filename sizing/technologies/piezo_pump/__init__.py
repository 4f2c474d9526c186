"""The frequency-rectified piezohydraulic pump."""
