"""Writes a generated file whole or not at all: the text goes to a temporary
file beside the target, which is then renamed over it, so an interrupted run
never leaves a truncated reference behind."""

import json
import os


def write_text(path, text):
    """Writes `text` (UTF-8, `\\n` line ends) to `path` atomically, creating
    its directory if needed."""
    directory = os.path.dirname(os.path.abspath(path))
    os.makedirs(directory, exist_ok=True)
    temporary = os.path.join(directory, f".{os.path.basename(path)}.{os.getpid()}.tmp")
    try:
        with open(temporary, "w", encoding="utf-8", newline="\n") as fh:
            fh.write(text)
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)


def write_json(path, document):
    """Writes a reference `document` as the references are kept: indented by
    one space, ending in a newline, and refused if it holds a NaN or an
    infinity (which JSON cannot carry)."""
    write_text(path, json.dumps(document, indent=1, allow_nan=False) + "\n")
