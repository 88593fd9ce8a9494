"""OpenSCENARIO export: a view model decided in Python, rendered by declarative Jinja2 templates."""
