"""Sizing engine: assemble candidates from catalog parts, size them with
geometric programs, verify them by simulation, rank them."""
