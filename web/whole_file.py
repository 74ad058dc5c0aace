"""Files the web build writes are whole or absent, as every file the suite writes: the text goes
to a temporary beside the destination, is flushed and synced, and is renamed over it last."""
import os
import tempfile


def write_whole(path, text):
    fd, temporary = tempfile.mkstemp(prefix="." + path.name + ".", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.chmod(temporary, 0o644)
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise
