"""Result files written in full or not at all (docs/runtime.md, "Result files"), the Python side of
rbdc/result_file.hpp: the data goes to "<path>.<pid>.partial" beside the target and is renamed onto
it when complete, so an interrupted run (an exception, SIGINT, SIGTERM) leaves the previous result.

    from result_files import replacing, write_result
    write_result("table.md", text)
    with replacing("plot.png") as partial:
        figure.savefig(partial, format="png")
"""

import contextlib
import os


@contextlib.contextmanager
def replacing(path):
    """Yields a temporary path beside `path`; renamed onto `path` when the block ends normally,
    removed when it raises (KeyboardInterrupt and SystemExit included)."""
    partial = "%s.%d.partial" % (os.fspath(path), os.getpid())
    try:
        yield partial
        os.replace(partial, path)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            os.remove(partial)
        raise


def write_result(path, text):
    """Writes `text` to `path` through replacing()."""
    with replacing(path) as partial, open(partial, "w", encoding="utf-8") as out:
        out.write(text)


def save_figure(figure, path, **options):
    """figure.savefig(path, **options) through replacing(); the format from the file extension."""
    with replacing(path) as partial:
        figure.savefig(partial, format=os.path.splitext(os.fspath(path))[1][1:], **options)
