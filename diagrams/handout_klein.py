"""The handout's sections for the classic constructions and the equivalent linkages.

:func:`sections` gives the HTML a handout adds before its end when the scene asks for Klein's
construction (``[diagram] klein``) or states a higher pair ([cams], [curved_slots], [rolling],
[bearing]): the finished Klein figure with the construction in words and its numbers, and the
equivalent linkage in words with the follower's motion.  Numbers come from
:mod:`polygons.classic.klein` and :mod:`polygons.contacts`; text is escaped here.
"""
from __future__ import annotations

from .html import esc, inline_svg, svg_size

#: printed width of the Klein figure, mm (the portrait page's text width)
WIDTH_MM = 180.0


def sections(sol, scale=None, paper=None) -> str:
    """The HTML sections (possibly empty) for ``sol``'s scene."""
    out = []
    method = sol.scene.options.diagram.klein
    if method:
        from polygons.classic.klein import TITLES, figure, report_lines
        from . import klein
        from .svg import to_svg
        fig = figure(sol, method)
        svg = to_svg(klein.drawing(sol, fig, None, scale, paper))
        w, _ = svg_size(svg)
        lines = report_lines(fig)
        out.append(f'<section id="klein">\n<h2>{esc(TITLES[method])}</h2>\n'
                   f'<figure class="diagram full">'
                   f'{inline_svg(svg, "klein", "figure", min(w, WIDTH_MM), TITLES[method])}'
                   f"</figure>\n<pre style='white-space: pre-wrap'>{esc(chr(10).join(lines))}</pre>\n</section>\n")
    if sol.scene.equivalents:
        from polygons.contacts import report_lines as equivalent_lines
        from . import rolling
        from .svg import to_svg
        figs = ""
        for d in rolling.drawings(sol, None, paper):      # a wheel on a moving surface
            svg = to_svg(d)
            w, _ = svg_size(svg)
            figs += (f'<figure class="diagram full">'
                     f'{inline_svg(svg, d.name, "figure", min(w, WIDTH_MM), d.name)}</figure>\n')
        out.append('<section id="equivalent">\n<h2>Equivalent linkage</h2>\n' + figs +
                   f"<pre style='white-space: pre-wrap'>{esc(chr(10).join(equivalent_lines(sol)))}</pre>\n</section>\n")
    return "".join(out)
