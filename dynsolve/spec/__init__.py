"""Safe parsing of spec text into immutable statements (never evaluated)."""
