"""Modules and libraries: instantiate, flatten and extract reusable sub-scenarios."""
