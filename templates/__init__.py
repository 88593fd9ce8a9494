"""Jinja2 model-to-text templates for OpenSCENARIO, installed as the package sceml.templates."""
