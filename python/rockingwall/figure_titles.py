"""Titles that fit their figure: each line of a title wrapped to the width the figure gives it,
so that a long scene description is read whole rather than cut off at the figure's edges."""
import textwrap

CHAR_WIDTH = 0.55  # a character's average width, in points per point of font size


def wrapped(text, width):
    """Each line of text wrapped to width characters."""
    return "\n".join(part for line in text.splitlines() for part in textwrap.wrap(line, width))


def suptitle(fig, text, fontsize):
    """fig's title: text, each line wrapped to the figure's width (at least 40 characters)."""
    width = max(40, int(fig.get_figwidth() * 72 / (CHAR_WIDTH * fontsize)))
    fig.suptitle(wrapped(text, width), fontsize=fontsize)
