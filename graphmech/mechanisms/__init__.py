"""What is analysed: the mechanisms themselves (no drawing, no checking)."""
