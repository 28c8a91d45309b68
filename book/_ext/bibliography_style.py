"""Author-year labels for the bibliography: "Surriani et al. 2018", "Lynch and Park
2017".

Registers with pybtex a label, a sorting (by label) and a formatting style, all named
``author_year_labels`` (``bibtex_default_style`` in ``_config.yml``). An entry whose
authors are unknown gives its label in a ``shorthand`` field ("CX210L study 2021")
instead of inventing an author.
"""

import pybtex.plugin
from pybtex.style.formatting.unsrt import Style as UnsrtStyle
from pybtex.style.labels import BaseLabelStyle
from pybtex.style.sorting import BaseSortingStyle

NAME = "author_year_labels"


def _surname(person):
    return " ".join(person.prelast_names + person.last_names) or " ".join(
        person.first_names
    )


def author_year_label(entry):
    """The label of one pybtex entry, e.g. 'Surriani et al. 2018'."""
    if "shorthand" in entry.fields:
        return str(entry.fields["shorthand"])
    persons = entry.persons.get("author") or entry.persons.get("editor") or []
    names = [_surname(p).replace("{", "").replace("}", "") for p in persons]
    if not names:
        raise ValueError(
            f"bibliography entry {entry.key!r} has no author, editor or shorthand"
        )
    if len(names) == 1:
        who = names[0]
    elif len(names) == 2:
        who = f"{names[0]} and {names[1]}"
    else:
        who = f"{names[0]} et al."
    return f"{who} {entry.fields.get('year', 'n.d.')}"


class AuthorYearLabels(BaseLabelStyle):
    def format_labels(self, sorted_entries):
        for entry in sorted_entries:
            yield author_year_label(entry)


class ByLabel(BaseSortingStyle):
    """Entries in the alphabetical order of their labels, as a reader looks them up."""

    def sorting_key(self, entry):
        return author_year_label(entry).lower()


class AuthorYearStyle(UnsrtStyle):
    default_label_style = NAME
    default_sorting_style = NAME


def setup(app):
    pybtex.plugin.register_plugin("pybtex.style.labels", NAME, AuthorYearLabels)
    pybtex.plugin.register_plugin("pybtex.style.sorting", NAME, ByLabel)
    pybtex.plugin.register_plugin("pybtex.style.formatting", NAME, AuthorYearStyle)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
