"""Abstraction levels: concretize, promote, and sample logical scenarios into concrete ones."""
