"""Tools for SceML's own development: regenerating `generated/`, class diagrams of the
metamodel, and keeping a metamodel release (`sceml dev ...`)."""
