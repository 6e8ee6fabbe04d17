"""Batch grading: per-student variants, expected answers, grading, diagnosis and reports."""
