"""The page side of the viewers: the one script of ``static/viewer/``, three.js shipped
once per page, and the :class:`Viewer` figure that carries a model as JSON.

A figure builder (:mod:`screwkit.viewer`) hands :class:`Viewer` only parameters; this
module packages the JavaScript (the files of ``static/viewer/`` joined in the order of
``VIEWER_PARTS``, three.js vendored and deflated) and writes the HTML.
"""

import base64
import hashlib
import html
import itertools
import json
import re
import zlib
from importlib import resources

import numpy as np

from ._checks import (
    as_float_array,
    check_flag,
    describe,
)

_ids = itertools.count(1)


_library = {"shipped": False, "script": None}


#: The parts of the viewers' one script (package data ``screwkit/static/viewer/``), in
#: the order they are joined: together they are the body of one function, written once
#: per page. Each file is one concern; the join adds nothing between them.
VIEWER_PARTS = (
    "header.js",  # what the script is; the function's start; run once per page
    "kinematics.js",  # exp of a twist, a chain's FK, Jacobian, ellipsoid, platform legs
    "style.js",  # the viewers' stylesheet and a DOM element helper
    "scene.js",  # the three.js stage: renderer, camera, meshes, framing, labels
    "controls.js",  # the stage's pointer, wheel, keyboard and resize handlers
    "figures.js",  # robot, trajectory, screw motion, platform, mechanism on a stage
    "page.js",  # sliders, readouts, aria-live captions, mounting, window.screwkit
)


def viewer_script():
    """The JavaScript of every viewer: the files of ``VIEWER_PARTS`` joined in order.

    Returns
    -------
    str
        One classic script that defines ``window.screwkit`` and mounts the page's
        viewers.
    """
    folder = resources.files("screwkit").joinpath("static/viewer")
    return "".join(
        folder.joinpath(part).read_text(encoding="utf-8") for part in VIEWER_PARTS
    )


def _vendored(name):
    return (
        resources.files("screwkit")
        .joinpath(f"static/vendor/{name}")
        .read_text(encoding="utf-8")
    )


def _classic_three():
    """three.js as a classic script that sets ``window.THREE`` (once: guarded in the
    page).

    The vendored file is npm's ``three/build/three.module.min.js``, byte for byte; its
    one ``export {local as Name, ...}`` clause becomes ``window.THREE = {Name: local,
    ...}`` inside a function, so that the page needs no module loader and no URL.
    """
    source = _vendored("three.module.min.js")
    start = source.rindex("export{")
    end = source.index("}", start)
    if source[end + 1 :].strip() not in ("", ";"):
        raise RuntimeError("three.module.min.js does not end with its export clause")
    names = []
    for item in source[start + len("export{") : end].split(","):
        match = re.fullmatch(r"\s*([\w$]+)(?:\s+as\s+([\w$]+))?\s*", item)
        if match is None:
            raise RuntimeError(f"three.module.min.js: cannot read the export {item!r}")
        local, name = match.group(1), match.group(2) or match.group(1)
        names.append(f"{name}:{local}")
    return (
        'if(!window.THREE){(function(){"use strict";'
        + source[:start]
        + ";window.THREE={"
        + ",".join(names)
        + "};})();}"
    )


def library_script():
    """The script that puts three.js in the page (a classic script, deflated).

    three.js travels as raw deflate in base64 (221 kB instead of 668 kB); npm's
    tiny-inflate (vendored too) inflates it synchronously and the text runs as a script
    element, so that ``window.THREE`` exists before the next script of the page runs.
    Then it mounts every viewer that was waiting for it.

    Returns
    -------
    str
        The script's JavaScript text.

    Examples
    --------
    It defines three.js only where the page lacks it:

    >>> library_script().startswith("if(!window.THREE)")
    True
    """
    if _library["script"] is None:
        text = _classic_three().encode("utf-8")
        packer = zlib.compressobj(9, zlib.DEFLATED, -15)
        packed = base64.b64encode(packer.compress(text) + packer.flush()).decode(
            "ascii"
        )
        _library["script"] = (
            "if(!window.THREE){(function(){var module={exports:{}};"
            "(function(module){" + _vendored("tiny-inflate.js") + "\n})(module);"
            f'var b=atob("{packed}"),z=new Uint8Array(b.length),i;'
            "for(i=0;i<b.length;i++)z[i]=b.charCodeAt(i);"
            f"var t=new Uint8Array({len(text)});module.exports(z,t);"
            'var s=document.createElement("script");'
            "s.textContent=new TextDecoder().decode(t);"
            "(document.head||document.documentElement).appendChild(s);})();}"
            "if(window.screwkit)window.screwkit.mountAll();"
        )
    return _library["script"]


def resend_library():
    """Ship three.js again with the next viewer (after the output that carried it was
    cleared).

    Examples
    --------
    >>> import screwkit as sk
    >>> resend_library()
    >>> library_script() in sk.viewer.robot_viewer(sk.robots.planar([1.0, 0.5])).html()
    True
    """
    _library["shipped"] = False


#: What a 3D viewer shows until three.js is in the page (removed when it mounts).
_WAITING = (
    '<div class="screwkit-note">Waiting for the 3D library, which comes with the '
    "first 3D viewer of this page or kernel session (if that output was cleared, run "
    "<code>screwkit.viewer.resend_library()</code> and show this figure again).</div>\n"
)


class Viewer:
    """A figure for the page, drawn by ``viewer.js``.

    Parameters
    ----------
    model : dict
        The figure's parameters, JSON-ready.
    summary : str
        Its plain-text form (what a terminal or a text-only output shows).

    Examples
    --------
    What the viewers return: a model for ``viewer.js`` and its text.

    >>> import screwkit as sk
    >>> figure = sk.viewer.screw_motion_viewer([0, 0, 1], [1, 0, 0], 0)
    >>> isinstance(figure, Viewer), figure.model["kind"], figure.model["h"]
    (True, 'screw', 0.0)
    """

    def __init__(self, model, summary):
        self.model = model
        self.summary = summary
        payload = json.dumps(model, sort_keys=True, separators=(",", ":"))
        digest = hashlib.sha1(payload.encode()).hexdigest()[:10]
        self.id = f"screwkit-{digest}-{next(_ids)}"
        self._payload = payload
        self._carries_library = None

    def __repr__(self):
        return self.summary

    def html(self, library=None):
        """The figure's HTML.

        three.js and ``viewer.js`` come together. By default (None) they come with every
        3D figure until one has been displayed on its own (``_repr_mimebundle_``, what
        Jupyter and the book call), then with that figure only: once per kernel session,
        so once per page of the book; later figures carry only their parameters and
        mount when the scripts are in the page, in whatever order the outputs are
        rendered. A figure shown as the page fallback of a live widget (``_repr_html_``)
        carries them while none has been displayed, since Lab may draw the widget
        instead. Stepped figures need no three.js and always carry ``viewer.js``.

        Parameters
        ----------
        library : bool or None, optional
            True/False: include three.js and ``viewer.js`` or not; None: as above.

        Returns
        -------
        str
            The HTML: the figure's container, its parameters and the call that
            mounts it, after three.js and ``viewer.js`` when they come with it.

        Examples
        --------
        Without the library a figure is its parameters and one call to mount it:

        >>> import screwkit as sk
        >>> figure = sk.viewer.screw_motion_viewer([0, 0, 1], [1, 0, 0], 0)
        >>> text = figure.html(library=False)
        >>> f'id="{figure.id}"' in text, library_script() in text
        (True, False)
        """
        if library is not None:
            library = check_flag(library, "library")
        needs = self.model["kind"] != "steps"
        if library is None:
            library = self._carries_library
            if library is None:
                library = needs and not _library["shipped"]
        payload = self._payload.replace("</", "<\\/")
        note = "" if not needs else _WAITING
        parts = [
            f'<div class="screwkit-viewer" id="{self.id}">\n'
            f'<script type="application/json">{payload}</script>\n{note}'
            f"<noscript>{html.escape(self.summary)}</noscript>\n</div>\n"
        ]
        if library and needs:
            parts.append(f"<script>\n{library_script()}\n</script>\n")
        if library or not needs:  # later 3D viewers use the script already in the page
            parts.append(f"<script>\n{viewer_script()}</script>\n")
        parts.append(
            f"<script>window.screwkit && window.screwkit.mount("
            f"document.getElementById({json.dumps(self.id)}) || "
            "document.currentScript.parentNode.querySelector("
            f"\"[id='{self.id}']\"));</script>\n"
        )
        return "".join(parts)

    def _repr_html_(self):
        return self.html()

    def _repr_mimebundle_(self, include=None, exclude=None):
        if self._carries_library is None:
            self._carries_library = (
                self.model["kind"] != "steps" and not _library["shipped"]
            )
            _library["shipped"] = _library["shipped"] or self._carries_library
        return {"text/plain": self.summary, "text/html": self.html()}

    def page(self, title=None):
        """A whole HTML page holding this figure and three.js (for a file or a
        browser).

        Parameters
        ----------
        title : str or None, optional
            The page's title; by default the model's name, else "screwkit viewer".

        Returns
        -------
        str
            The page's HTML.

        Examples
        --------
        >>> import screwkit as sk
        >>> page = sk.viewer.screw_motion_viewer([0, 0, 1], [1, 0, 0], 0).page("A turn")
        >>> page.startswith("<!DOCTYPE html>"), "<title>A turn</title>" in page
        (True, True)
        """
        if title is not None and not isinstance(title, str):
            raise TypeError(f"title must be a str or None, got {describe(title)}")
        title = html.escape(title or self.model.get("name") or "screwkit viewer")
        return (
            '<!DOCTYPE html><html lang="en"><head><meta charset="utf-8">'
            '<meta name="viewport" content="width=device-width, initial-scale=1">'
            f"<title>{title}</title></head><body>\n{self.html(library=True)}"
            "</body></html>\n"
        )


def _numbers(array, digits=12):
    """Nested lists of floats rounded to ``digits`` significant digits (stable JSON)."""
    return np.vectorize(lambda x: float(f"{x:.{digits}g}") + 0.0)(
        np.asarray(array)
    ).tolist()


def _check_size(size):
    values = as_float_array(size, "size")
    if values.shape != (2,) or np.any(values < 100) or np.any(values > 2000):
        raise ValueError(
            f"size must be (width, height) in pixels, each in [100, 2000], got {size!r}"
        )
    return int(values[0]), int(values[1])
