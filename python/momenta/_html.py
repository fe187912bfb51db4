"""Results as notebooks show them (_repr_html_): what the repr prints, laid out as HTML. A table
of modes has the cells `momenta modes` prints (one rule for round-off, in C++); a run shows its
size, the unit of every column and its first and last rows; every other result its repr text."""

import html as _html


def _table(header, rows, caption=""):
    head = "".join(f"<th>{_html.escape(str(h))}</th>" for h in header)
    body = "".join("<tr>" + "".join(f"<td>{_html.escape(str(c))}</td>" for c in row) + "</tr>" for row in rows)
    title = f"<caption>{_html.escape(caption)}</caption>" if caption else ""
    return f"<table>{title}<thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def modes_html(modes):
    header, rows = modes._table_cells()
    return _table(header, rows, f"{len(modes)} modes of {len(modes.state_names)} states")


def simulation_html(result, shown=3):
    """The run's first and last `shown` rows, every column headed by its name and unit."""
    units = result.units
    header = [f"{name} ({units[name]})" if units[name] not in ("", "1") else name
              for name in result.columns]
    count = len(result)
    picks = list(range(count)) if count <= 2 * shown else [*range(shown), None, *range(count - shown, count)]
    rows = [["…"] * len(header) if i is None else [f"{x:.6g}" for x in result.data[i]] for i in picks]
    return _table(header, rows, repr(result).strip("<>"))


def text_html(result):
    return f"<pre>{_html.escape(repr(result))}</pre>"
