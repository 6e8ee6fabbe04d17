"""Batch grading: per-student variants, expected answers, grading and reports."""
