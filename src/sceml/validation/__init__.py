"""Validation: constraint functions registered per metaclass, collected into diagnostics."""
