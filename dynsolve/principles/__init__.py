"""Principles: each turns a scene model into the textbook equations, nothing else."""
