"""Diagrams in the SceML notation and as behavior trees, and the HTML review report."""
