"""OpenSCENARIO facts and file checking, below validation and export: both read it.

The versions and profiles SceML writes and what each can express (`support`, `profiles`).
"""
