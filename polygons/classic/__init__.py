"""The classic graphical constructions read off a solved instant (interpreters layer).

:mod:`polygons.classic.klein`: Klein's and Ritterhaus's constructions for the slider-crank.
Each builds its own figure from the space diagram (points, lines and circles intersected
through :mod:`polygons.geometry`) and reports the numbers read off it beside the polygons'.
"""
