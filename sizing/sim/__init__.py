"""Batch simulators: many candidates at once, compiled with numba."""
