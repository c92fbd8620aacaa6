"""Question banks: templates per family, seeded variants whose answers the
real algorithms compute, and writers for the quiz tools (model.py says what
a question is made of)."""
