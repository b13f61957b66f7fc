#!/usr/bin/env python3
"""Generate the exercise pages from one template: each exercise of the catalogue (the JSON that
examples/catalog_main.cpp prints from examples/exercise_list.cpp) becomes NAME.html from
page.html.in, its controls written from the option table's types, labels and choices; index.html
lists them from index.html.in, each with its picture (web/thumbs/NAME.png, rendered by
scripts/thumbs.sh and copied into the site by the web build) where there is one. The page script (penumbra-page.js) binds any control that carries
data-option, so nothing here is specific to one exercise or one option.

usage: pages.py CATALOG.json WEB_DIR OUT_DIR
"""
import html
import json
import pathlib
import string
import sys


def esc(s: str) -> str:
    return html.escape(s, quote=True)


def choices_of(option: dict, control: dict) -> list:
    """The (value, label) pairs a select or radio group offers."""
    # An integer's words (map-size auto) are among its presets.
    pool = option["presets"] if option["type"] == "integer" and option["presets"] else option["choices"] or option["presets"]
    labels = {c["value"]: c["label"] for c in pool}
    values = control["values"] or [c["value"] for c in pool]
    # A list option's value ("outline,mirror"): its choices' labels joined.
    return [(v, " + ".join(labels.get(part, part) for part in v.split(","))) for v in values]


def control_html(option: dict, control: dict) -> str:
    name = option["name"]
    label = control["label"] or option["label"]
    kind = control["kind"]
    hint_id = f"{name}-hint"
    hint = f'\n        <span class="hint" id="{hint_id}">{esc(control["hint"])}</span>' if control["hint"] else ""
    described = f' aria-describedby="{hint_id}"' if control["hint"] else ""
    if kind == "toggle":
        on = option["default"] == "on"
        return (f'<button type="button" id="{name}" data-option="{name}" aria-pressed="{str(on).lower()}">'
                f'{esc(label)}: <span class="state">{"on" if on else "off"}</span></button>')
    if kind == "radio":
        return "\n".join(f'<div class="row"><label><input type="radio" name="{name}" data-option="{name}" '
                         f'value="{esc(v)}"> {esc(text)}</label></div>' for v, text in choices_of(option, control))
    if kind == "select":
        items = "".join(f'\n          <option value="{esc(v)}">{esc(text)}</option>' for v, text in choices_of(option, control))
        return (f'<div class="row"><label for="{name}">{esc(label)}</label>\n'
                f'        <select id="{name}" data-option="{name}"{described}>{items}\n        </select>{hint}</div>')
    if kind == "checkbox":
        on, off = control["values"] if control["values"] else ("on", "off")
        return (f'<div class="row"><label><input type="checkbox" id="{name}" data-option="{name}" '
                f'data-on="{esc(on)}" data-off="{esc(off)}"{described}> {esc(label)}</label>{hint}</div>')
    if kind == "number":
        # A radio per word (its value shown beside it by the page script), one for a number of
        # the user's, and the number box; the script sends the word or the number.
        rows = [f'<div class="row"><label><input type="radio" name="{name}-mode" id="{name}-{esc(c["value"])}" '
                f'value="{esc(c["value"])}"> {esc(c["label"])} (<span id="{name}-{esc(c["value"])}-value"></span>)'
                f'</label></div>' for c in option["choices"]]
        limits = "".join(f' {k}="{option[k]:g}"' for k in ("min", "max") if option[k] is not None)
        step = f' step="{option["step"]:g}"' if option["step"] else ""
        rows.append(f'<div class="row"><label><input type="radio" name="{name}-mode" id="{name}-fixed" value="fixed"> '
                    f'fixed:</label>\n          <input type="number" id="{name}"{limits}{step} inputmode="decimal">\n'
                    f'          <label for="{name}" class="hint">{esc(control["hint"])}</label></div>')
        inner = "\n        ".join(rows)
        return (f'<fieldset class="choices" id="{name}-mode">\n        <legend>{esc(label)}</legend>\n'
                f'        {inner}\n      </fieldset>')
    if kind == "slider":
        # A slider over the control's range and a number box over the option's (the same option:
        # the page script keeps both in step), the value beside it.
        step = f' step="{option["step"]:g}"' if option["step"] else ' step="any"'
        limits = "".join(f' {k}="{option[k]:g}"' for k in ("min", "max") if option[k] is not None)
        # The number box is labelled by the hint (its unit), as the bias's number box is.
        return (f'<div class="row"><label for="{name}">{esc(label)}</label>\n'
                f'        <input type="range" id="{name}" data-option="{name}" min="{control["min"]:g}" '
                f'max="{control["max"]:g}"{step}>\n'
                f'        <input type="number" id="{name}-number" data-option="{name}"{limits}{step} inputmode="decimal">\n'
                f'        <label for="{name}-number" class="hint">{esc(control["hint"] or label)}</label></div>')
    sys.exit(f"pages.py: control kind '{kind}' of '{name}' is not known")


def controls_html(exercise: dict, options: dict) -> str:
    """The controls in fieldsets, one per group, in the catalogue's order; buttons share a row."""
    out, group, body = [], None, []

    def close():
        if group is not None:
            out.append(f'    <fieldset>\n      <legend>{esc(group)}</legend>\n      ' + "\n      ".join(body) +
                       "\n    </fieldset>")

    buttons = []
    for c in exercise["controls"]:
        if c["group"] != group:
            if buttons:
                body.append('<div class="row">\n        ' + "\n        ".join(buttons) + "\n      </div>")
                buttons = []
            close()
            group, body = c["group"], []
        piece = control_html(options[c["option"]], c)
        if c["kind"] == "toggle":
            buttons.append(piece)
            continue
        if buttons:
            body.append('<div class="row">\n        ' + "\n        ".join(buttons) + "\n      </div>")
            buttons = []
        body.append(piece)
    if buttons:
        body.append('<div class="row">\n        ' + "\n        ".join(buttons) + "\n      </div>")
    close()
    return "\n".join(out)


def fly_html(exercise: dict) -> str:
    """The fly camera's panel (an exercise with a scene of its own, "fly" in the catalogue): buttons for
    each move, read by penumbra-page.js (data-fly), and the camera's position."""
    if not exercise.get("fly"):
        return ""
    moves = [("forward", "Forward"), ("back", "Back"), ("left", "Left"), ("right", "Right"),
             ("turn-left", "Turn left"), ("turn-right", "Turn right"), ("look-up", "Look up"),
             ("look-down", "Look down"), ("rise", "Up"), ("sink", "Down")]
    buttons = "\n        ".join(f'<button type="button" data-fly="{m}">{esc(text)}</button>' for m, text in moves)
    return ("    <fieldset id=\"fly\">\n      <legend>Camera</legend>\n"
            "      <p class=\"hint\" id=\"fly-hint\">Drag the picture to look around. Click it, then W A S D or the "
            "arrow keys move, Q and E go down and up, Shift goes 10 times as far.</p>\n"
            f"      <div class=\"row fly-buttons\">\n        {buttons}\n"
            "        <button type=\"button\" data-fly=\"reset\">Scene camera</button>\n      </div>\n"
            "      <p class=\"readout\">Camera: <output id=\"camera\" for=\"canvas\">–</output></p>\n"
            "    </fieldset>\n")


# The pages with the shader lab (docs/pages.md, docs/snippets.md): the sheet's shadow-map code
# (packDepth, unpackDepth, shadowTest, offset_lookup) fits W09P2c, whose controls hold the encoding
# and the 4x4 PCF the lab's snippets replace.
LAB_EXERCISES = {"w09p2c"}  # and web/CMakeLists.txt's PENUMBRA_LAB_PAGES (their modules export the lab), Exercise::lab


def lab_html(exercise: dict) -> str:
    """The shader lab's button and its (empty) panel: web/lab/lab.js and the editor are loaded and
    the panel filled only when the button is pressed (or the address holds #lab=...)."""
    if exercise["name"] not in LAB_EXERCISES:
        return ""
    return ('    <fieldset id="lab-open-row">\n      <legend>Shader lab</legend>\n'
            '      <div class="row"><button type="button" id="lab-open" aria-expanded="false" aria-controls="lab">'
            'Shader lab</button>\n        <span class="hint">write the sheet\'s shader code; it is checked</span></div>\n'
            '    </fieldset>\n')


def write_if_changed(path: pathlib.Path, text: str) -> None:
    if not path.exists() or path.read_text() != text:
        path.write_text(text)


def main() -> None:
    catalog = json.loads(pathlib.Path(sys.argv[1]).read_text())
    web, out = pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    out.mkdir(parents=True, exist_ok=True)
    page = string.Template((web / "page.html.in").read_text())
    index = string.Template((web / "index.html.in").read_text())
    items = []
    for ex in catalog["exercises"]:
        write_if_changed(out / f'{ex["name"]}.html', page.substitute(
            name=ex["name"], title=esc(ex["title"]), text=esc(ex["text"]), look_for=esc(ex["lookFor"]),
            canvas=esc(ex["canvas"]),
            controls=controls_html(ex, catalog["options"]), fly=fly_html(ex), lab=lab_html(ex),
            lab_panel=('<section class="lab" id="lab" aria-label="Shader lab" hidden></section>\n'
                       if ex["name"] in LAB_EXERCISES else "")))
        thumb = ""
        if (web / "thumbs" / f'{ex["name"]}.png').exists():
            thumb = (f'<a href="{ex["name"]}.html" tabindex="-1" aria-hidden="true"><img src="thumbs/{ex["name"]}.png" '
                     f'width="128" height="128" alt=""></a>\n    ')
        items.append(f'  <li>{thumb}<div><a href="{ex["name"]}.html">{esc(ex["title"])}</a>\n    '
                     f'<p>{esc(ex["brief"])}</p></div></li>')
    write_if_changed(out / "index.html", index.substitute(exercises="\n".join(items)))


if __name__ == "__main__":
    main()
