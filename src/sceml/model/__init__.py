"""Models in memory and on disk: loading and saving XMI safely, building, copying and querying.

`loading`, `saving`, `documents`, `locating` and `xmiresource` are what `sceml.model` was;
`build` makes models in code, `copying` copies subtrees, `graph`, `params` and `catalog`
answer questions about a model, `migrating` rewrites files of older releases.
"""
