"""Batch grading of a class's answers: cells, semantics, diagnosis, reports, resume."""
