"""The handout's sections for the drawing board's force methods: the force polygons per Assur
group and Zhukovsky's lever, where the scene asks for them (``[handout] force_polygons``,
``[handout] zhukovsky``).

:func:`check` refuses, in one line naming the method and what the mechanism lacks, a scene
asking for a method it does not support (the method's own refusal, prefixed with the key);
:func:`sections` gives the HTML inserted before the handout's end (by
:mod:`polygons.cli.handout`, as Klein's section is): per state, each group's finished force
polygon (:func:`diagrams.forcepoly.group_drawings`) with the construction in words and the
reactions it found, and the finished lever (:func:`diagrams.forcepoly.lever_drawings`) with
every force's moment about the pole and the balancing effort.  Every number is a record of
:mod:`polygons.forces.graphical` / :mod:`polygons.forces.zhukovsky` (which the tests hold
equal to Newton–Euler and to the virtual work); nothing is recomputed here.  Text is escaped
and typeset (:func:`diagrams.html.sym`).
"""
from __future__ import annotations

import math
import re

import numpy as np

from polygons.errors import SceneError, UnsupportedError
from polygons.report import sense

from .audit import MIN_TEXT_MM
from .html import esc, inline_svg, svg_size, sym

#: printed width available to a figure, mm (the portrait page's text width)
WIDTH_MM = 180.0


def asked(sol) -> tuple[bool, bool]:
    """(force polygons, Zhukovsky's lever) as the scene's ``[handout]`` asks."""
    ho = sol.scene.options.handout
    return ho.force_polygons, ho.zhukovsky


def _refused(key: str, e, file) -> UnsupportedError:
    """The method's own one-line refusal, located at the key that asked for it."""
    why = e if isinstance(e, str) else getattr(e, "reason", None) or str(e)
    return UnsupportedError(f"{key} = true: {why}", file=file, where=f"handout.{key}")


def check(sol):
    """The force analysis the asked sections need (None when none is asked); refused in one
    line when the scene has no loads or the mechanism is not one the method handles."""
    polys, lever = asked(sol)
    if sol.scene.options.handout.turning_moment:
        from polygons.forces import has_forces
        if not has_forces(sol.scene):
            raise SceneError("turning_moment = true asks for a force method, but the scene "
                             "has no [masses], [forces], [torques] or [springs]",
                             file=sol.scene.file, where="handout.turning_moment")
        try:
            _cycle(sol)
        except UnsupportedError as e:
            raise _refused("turning_moment", e, sol.scene.file) from None
        if not (polys or lever):
            from polygons.forces import analyse
            return analyse(sol.scene)
    if not (polys or lever):
        return None
    from polygons.forces import analyse, has_forces, graphical, zhukovsky
    scene = sol.scene
    if not has_forces(scene):
        key = "force_polygons" if polys else "zhukovsky"
        raise SceneError(f"{key} = true asks for a force method, but the scene has no "
                         f"[masses], [forces], [torques] or [springs]", file=scene.file,
                         where=f"handout.{key}")
    if polys:
        try:
            graphical.groups_of(scene)
        except UnsupportedError as e:
            raise _refused("force_polygons", e, scene.file) from None
    an = analyse(scene)
    for st in an.states:
        if polys:
            try:
                graphical.construct(an, st)
            except UnsupportedError as e:
                raise _refused("force_polygons", e, scene.file) from None
        if lever:
            try:
                zhukovsky.construct(an, st)
            except UnsupportedError as e:
                raise _refused("zhukovsky", e, scene.file) from None
    return an


def load_rows(lds, _g) -> list[tuple[str, str]]:
    """The force data of a scene with loads for the handout's data table, as the problem
    states them: masses, gravity, forces, couples, pin frictions and springs (``_g`` the
    table's number format)."""
    if lds is None or not lds.active:
        return []
    rows = [(f"mass {m.name}", f"{_g(m.mass)} kg on {m.body}" + (
        f"; its moment of inertia about its centre of mass {_g(m.inertia)} kg m² ({m.how})"
        if m.inertia else "")) for m in lds.masses]
    g = math.hypot(*lds.gravity)
    if g:
        rows.append(("gravity", f"g = {_g(g)} m/s² towards "
                                f"{_g(math.degrees(math.atan2(lds.gravity[1], lds.gravity[0])) % 360)}°"))
    for f in lds.forces:
        rows.append((f"force {f.name}", f"{f.how} at {f.at} on {f.body}" + (
            "; it acts only while it opposes its point's motion" if f.resisting else "")))
    rows += [(f"couple {t.name}", f"{_g(abs(t.torque))} N m {sense(t.torque)} on {t.body}")
             for t in lds.torques]
    rows += [(f"friction {fr.name}", f"{_g(fr.torque)} N m at the pin {fr.at}")
             for fr in lds.frictions]
    rows += [(f"spring {s.name}", f"{s.kind}, stiffness {_g(s.stiffness)} "
                                 f"{'N m/rad' if s.kind == 'torsional' else 'N/m'}")
             for s in lds.springs]
    return rows


# ---------------------------------------------------------------- numbers in words
def _n(x: float) -> str:
    """A force or moment as ``polygons forces`` prints it (6 significant figures)."""
    s = f"{x:.6g}"
    return s.replace("-", "−")


def _deg(v) -> str:
    return f"{math.degrees(math.atan2(v[1], v[0])) % 360.0:.2f}°"


def effort_words(an, e: float, st=None) -> str:
    """The balancing effort as ``polygons forces`` states it (8 significant figures), in the
    one formatter's words (:func:`polygons.forces.words.effort_words`)."""
    from polygons.forces import words
    return words.effort_words(an.model, e, None if st is None else st.sol)


#: the lowest a reduced figure's text may print (mm): the layout audit's rule
MIN_PRINTED_TEXT = MIN_TEXT_MM


def printed(drawing):
    """(drawing, printed width mm, reduction) of a finished force drawing as the handout
    prints it: its key and legend moved below it where beside it they would be wider than
    the page and below it they are not (:func:`diagrams.layout.restack`); a drawing wider
    than the page even so is reduced to its width, its text set larger first so that every
    text still prints :data:`MIN_PRINTED_TEXT` mm high (size ≥ 2.0 / reduction: at the
    ×0.71 of a triad's joint, 2.8 mm labels become 2.82 mm and the bar's 2.6 mm figures too)."""
    from .layout import restack
    from .svg import to_svg
    w, _ = svg_size(to_svg(drawing))
    if w > WIDTH_MM:
        narrow = restack(drawing, WIDTH_MM)
        nw = svg_size(to_svg(narrow))[0]
        if nw <= WIDTH_MM:
            return narrow, nw, 1.0
        drawing, w = narrow, nw
    if w <= WIDTH_MM:
        return drawing, w, 1.0
    k = WIDTH_MM / w
    return _text_at_least(drawing, MIN_PRINTED_TEXT / k), WIDTH_MM, k


def _text_at_least(d, size: float):
    """``d`` with every text smaller than ``size`` (mm) set at ``size`` (rounded up to a
    hundredth), in place: a text's anchor point stays where it was."""
    from dataclasses import replace

    from .model import Group, Text
    size = math.ceil(size * 100.0) / 100.0

    def fix(it):
        if isinstance(it, Group):
            return replace(it, items=tuple(fix(i) for i in it.items))
        if isinstance(it, Text) and it.size < size:
            return replace(it, size=size)
        return it
    return replace(d, groups=tuple(fix(g) for g in d.groups))


def _figure(stem: str, drawing, title: str) -> str:
    """The finished drawing at its stated scale, as :func:`printed` sets it; a drawing
    reduced to the page width says so under it (its scale bar shrinks with it)."""
    from .svg import to_svg
    d, w, k = printed(drawing)
    note = ("" if k >= 1.0 else
            '<p class="figure-note">Reduced to the page width (its scale bar with it).</p>')
    fig = inline_svg(to_svg(d), stem, "figure", min(w, WIDTH_MM), title)
    return f'<figure class="diagram full">{fig}</figure>{note}\n'


_MINUS = re.compile(r"(?<![\w])-(?=[\d.])")


def _slug(name: str) -> str:
    """An HTML id part for a state's name ('after 30 deg' → 'after-30-deg')."""
    return re.sub(r"[^A-Za-z0-9]+", "-", name).strip("-") or "state"


def _state_heading(an, st) -> str:
    return f"<h3>{esc(st.name)}</h3>\n" if len(an.states) > 1 else ""


def _polygons(an) -> str:
    from polygons.forces import graphical
    from . import forcepoly
    out = ['<section id="force-polygons" class="forces">\n'
           "<h2>Force polygons per Assur group</h2>\n"
           "<p>The mechanism is taken apart into its Assur groups and solved as the drawing "
           "board does, the group furthest from the driver first. Each group is cut off at "
           "its outer pins and its loads, weights and inertia forces are applied — the "
           "inertia force −m a<sub>G</sub> drawn through the point offset from G by "
           "h = I<sub>G</sub> α / (m a<sub>G</sub>), so that it carries the inertia couple "
           "too — with the forces the groups already solved pass on through shared pins. "
           "The reaction at an outer pin is split into a component normal to its link, "
           "found by moments about the link's other pin, and one along it; the group's "
           "polygon then closes on the unknown sides. The crank comes last: its bearing "
           "force closes its polygon and the input effort is the moment about its pivot."
           "</p>\n"]
    for st in an.states:
        fp = graphical.construct(an, st)
        figs = {}
        for stem, d in forcepoly.group_drawings(an, st):
            if getattr(d, "stage", None) is None:
                figs[int(stem.rsplit("-", 1)[1])] = (stem, d)
        out.append(_state_heading(an, st))
        for g in fp.groups:
            out.append(f'<div class="force-group" id="force-group-{_slug(st.name)}-{g.index}">'
                       f"<h3>{sym(g.title[:1].upper() + g.title[1:])}</h3>\n"
                       '<ul class="construction">\n')
            for k in g.knowns:
                if k.pos is not None and k.force.any():
                    h = (f", offset h = {_n(k.offset * 1e3)} mm" if k.kind == "inertia"
                         else "")
                    out.append(f"<li>known: {sym(k.name)} = {_n(float(np.hypot(*k.force)))} "
                               f"N ∠{_deg(k.force)} on {esc(k.body)}{esc(h)}</li>\n")
                if k.couple:
                    out.append(f"<li>known: {sym(k.name)}, a couple of "
                               f"{esc(graphical.moment_words(k.couple))} on {esc(k.body)}</li>\n")
            for m in g.moments:            # a number's minus sign typeset as such
                out.append(f"<li>{sym(_MINUS.sub('−', m))}</li>\n")
            for f in g.normals:
                out.append(f"<li>by moments: {sym(f.name)} = "
                           f"{esc(graphical.found_words(f))}, normal to the link</li>\n")
            for f in g.closing:
                if f.how == "effort":
                    continue
                d = f.force if f.value else f.direction
                out.append(f"<li>the polygon closes on {sym(f.name)} = {_n(abs(f.value))} N "
                           f"∠{_deg(d)}</li>\n")
            for f in g.reactions:
                if f.how == "reaction":
                    out.append(f"<li>the diagonal gives {sym(f.name)} = {_n(f.value)} N "
                               f"∠{_deg(f.direction)}</li>\n")
            out.append("</ul>\n")
            if g.index in figs:
                stem, d = figs[g.index]
                out.append(_figure(stem, d, f"Force polygon of group {g.index}"))
            out.append("</div>\n")
        out.append(f'<table class="answer forces" id="force-polygon-reactions-{_slug(st.name)}">'
                   '\n<tr><th>pin'
                   '</th><th>force on</th><th class="n">F<sub>x</sub> N</th><th class="n">'
                   'F<sub>y</sub> N</th><th class="n">|F| N</th><th class="n">direction</th>'
                   "</tr>\n")
        for (lab, body), f in fp.pin.items():
            out.append(f"<tr><td>{esc(lab)}</td><td>{esc(body)}</td>"
                       f'<td class="n">{_n(float(f[0]))}</td><td class="n">{_n(float(f[1]))}'
                       f'</td><td class="n">{_n(float(np.hypot(*f)))}</td>'
                       f'<td class="n">{_deg(f) if f.any() else "–"}</td></tr>\n')
        out.append("</table>\n")
        diff = max([float(np.hypot(*(fp.pin[k] - v))) for k, v in st.ne.pin.items()
                    if k in fp.pin], default=0.0)
        from polygons.forces import effort
        out.append(f'<p class="force-effort"><strong>{esc(effort.words(an.model))}: '
                   f"{esc(effort_words(an, fp.effort, st))}</strong>; every reaction equals the "
                   f"Newton–Euler solution's (largest difference {diff:.1e} N).</p>\n")
        from polygons.forces.cams import words as contact_words
        for c in st.contacts:           # a cam's contact force: the force in its equivalent
            out.append(f'<p class="force-contact">{sym(contact_words(c))}.</p>\n')   # link
    out.append("</section>\n")
    return "".join(out)


def _lever(an) -> str:
    from polygons.forces import effort, words, zhukovsky
    from . import forcepoly
    out = ['<section id="zhukovsky" class="forces">\n<h2>Zhukovsky’s lever</h2>\n'
           "<p>The velocity polygon turned 90° counter-clockwise about its pole o is a rigid "
           "lever pivoted at o. Each force (inertia forces through their offset points) is "
           "applied parallel to itself at the turned image of its point; a couple C on a link "
           "AB as the pair ±C/AB normal to AB at a and b. A force's moment about o is minus "
           "the power it delivers: the effort balancing the moments is the virtual work's."
           "</p>\n"]
    unit = effort.unit(an.model)
    for st in an.states:
        lv = zhukovsky.construct(an, st)
        out.append(_state_heading(an, st))
        if lv.unit_rate:
            out.append("<p>The input is at rest: the lever is drawn on the velocity polygon "
                       "of a unit input rate.</p>\n")
        # the lever (~150 mm tall) after its table and sum: set before them it left half
        # the page above empty when it did not fit there, and its table's tail on a page
        # of its own (the toggle press's key: 7 pages -> 6)
        lever = [_figure(stem, d, "Zhukovsky's lever")
                 for stem, d in forcepoly.lever_drawings(an, st)
                 if getattr(d, "stage", None) is None]
        out.append(f'<table class="answer forces" id="zhukovsky-moments-{_slug(st.name)}">'
                   '\n<tr><th>force</th>'
                   '<th class="n">|F| N</th><th class="n">direction</th><th class="n">image '
                   '(turned) m/s</th><th class="n">moment about o, N m/s</th></tr>\n')
        ext = max([float(np.hypot(*a.lever)) for a in lv.applied + lv.effort_forces]
                  + [1e-300])
        for a in lv.applied + lv.effort_forces:     # a rounding residue (1e-17) shown as 0
            x, y = (0.0 if abs(c) < 1e-12 * ext else float(c) for c in a.lever)
            img = f"({_n(x)}, {_n(y)})"
            out.append(f"<tr><td>{sym(a.name)}</td><td class=\"n\">"
                       f"{_n(float(np.hypot(*a.force)))}</td><td class=\"n\">"
                       f"{_deg(a.force) if a.force.any() else '–'}</td><td class=\"n\">"
                       f"{img}</td><td class=\"n\">{words.table_moment(a.moment)}</td></tr>\n")
        out.append("</table>\n")
        vw = st.vw_effort
        vw_text = ("" if vw is None else
                   f"; by virtual work {esc(effort_words(an, vw, st))} (difference "
                   f"{abs(lv.effort - vw):.1e} {esc(unit)})")
        out.append(f'<p class="force-effort">{esc(words.lever_sum_words(an.model, lv))}: '
                   f"<strong>{esc(effort.words(an.model))}: "
                   f"{esc(effort_words(an, lv.effort, st))}</strong>{vw_text}.</p>\n")
        out += lever
    out.append("</section>\n")
    return "".join(out)


#: angles of the handout's turning-moment diagram (its drawn curve; the numbers do not depend on
#: them: polygons.forces.cycle)
CYCLE_ANGLES = 72


def _cycle(sol):
    """The turning-moment diagram of ``sol``'s scene, made once per solution (its memo)."""
    from polygons.memo import memo_of
    memo = memo_of(sol)
    if "turning_moment" not in memo:
        from polygons.forces.analysis import load_model
        from polygons.forces.cycle import turning_moment
        memo["turning_moment"] = turning_moment(load_model(sol.scene), sol.scene,
                                                CYCLE_ANGLES, table=False)
    return memo["turning_moment"]


def _turning_moment(sol) -> str:
    """The turning-moment diagram: the plot (T and E over the turn) and its numbers."""
    import tempfile
    from pathlib import Path
    from .plots import plot_turning_moment
    cy = _cycle(sol)
    scene = sol.scene
    with tempfile.TemporaryDirectory() as tmp:
        plot_turning_moment(cy, scene, Path(tmp) / "tm", "Turning-moment diagram",
                            formats=("svg",))
        svg = (Path(tmp) / "tm.svg").read_text(encoding="utf-8")
    svg = svg[svg.index("<svg"):]
    (t_hi, th_hi), (t_lo, th_lo) = cy.max_torque, cy.min_torque

    def at(t):
        return f"{round(math.degrees(t) % 360.0, 9) % 360.0:.4g}°"
    rows = [("maximum torque", f"{_n(t_hi)} N m at {at(th_hi)}"),
            ("minimum torque", f"{_n(t_lo)} N m at {at(th_lo)}"),
            ("mean torque T<sub>m</sub>", f"{_n(cy.mean)} N m"),
            ("maximum fluctuation of energy ΔE",
             f"{_n(cy.fluctuation)} J (E greatest at {at(cy.at_max)}, least at "
             f"{at(cy.at_min)})")]
    out = ['<section id="turning-moment" class="forces">\n<h2>The turning-moment diagram'
           '</h2>\n'
           f"<p>The input torque on {esc(scene.driver.link)} at {len(cy.theta)} angles round a "
           f"uniform turn (ω = {_n(abs(scene.driver.omega))} rad/s, α = 0; CCW positive), "
           "each found as above; E(θ) = ∫(T − T<sub>m</sub>) dθ is the energy above the "
           "mean, and a flywheel keeping the speed within ±C<sub>s</sub>/2 needs "
           "I = ΔE / (ω² C<sub>s</sub>). Virtual work equals Newton–Euler at every angle "
           f"(largest difference {cy.vw_error:.1e} N m).</p>\n",
           f'<figure class="diagram">{svg}</figure>\n',
           '<table class="answer forces" id="turning-moment-summary">\n']
    out += [f"<tr><th>{k}</th><td>{v}</td></tr>\n" for k, v in rows]
    out.append("</table>\n")
    out += [f'<p class="note">{esc(w)}</p>\n' for w in cy.warnings]
    out.append("</section>\n")
    return "".join(out)


def sections(sol, an) -> str:
    """The HTML sections (possibly empty) the scene asks for; ``an`` is :func:`check`'s."""
    if an is None:
        return ""
    polys, lever = asked(sol)
    return ((_polygons(an) if polys else "") + (_lever(an) if lever else "")
            + (_turning_moment(sol) if sol.scene.options.handout.turning_moment else ""))


__all__ = ["check", "sections", "asked", "effort_words"]
