"""@brief Atomic writes for the report generators: a file is written whole beside its target and
renamed over it, so a reader (the HTML report, a user) never meets half a figure set."""
import json
import os


def write_text_atomic(path, text):
    """@brief Writes `text` to `path` through `path`.tmp and a rename.
    @param path the file to (re)place
    @param text its whole content"""
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def write_json_atomic(path, obj):
    """@brief `obj` as indented JSON (one space) with a final newline, written atomically."""
    write_text_atomic(path, json.dumps(obj, indent=1) + "\n")


def save_figure_atomic(fig, path, **kwargs):
    """@brief A matplotlib figure saved atomically (format from the target's extension)."""
    root, ext = os.path.splitext(path)
    tmp = root + ".tmp" + ext
    fig.savefig(tmp, **kwargs)
    os.replace(tmp, path)
