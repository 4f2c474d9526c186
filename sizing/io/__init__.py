"""Edges of the tool: input files in, SI dataclasses out; atomic writes."""
