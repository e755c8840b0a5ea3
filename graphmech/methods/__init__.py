"""The textbook methods: each builds a construction (never draws, never reads files)."""
