"""The review page of `sceml report`: the page itself and the figures it shows.

`page` builds the HTML from the diagram, the diagnostics and the figures; `figures` makes the
figures (the map view in `mapfigure`, the preview run in `preview`), each a `figure.Figure`.
"""
