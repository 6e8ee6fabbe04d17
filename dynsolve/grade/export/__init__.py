"""Exports to the formats courses use: gradebooks (Canvas, Gradescope/Moodle CSV) and
a problem's variants as a Moodle XML quiz or a PrairieLearn question folder."""
