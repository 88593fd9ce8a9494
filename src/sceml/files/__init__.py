"""Safe access to files, below every stage: what may be read, hardened XML parsing, bounded
configuration files, and writing outputs atomically (alone or as a set)."""
