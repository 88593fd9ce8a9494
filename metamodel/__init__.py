"""The SceML Ecore metamodel, the single source of truth, installed as the package sceml.metamodel."""
