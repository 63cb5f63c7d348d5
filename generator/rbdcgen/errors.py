"""The one exception type the command line turns into "error: ..." and exit code 2."""


class RbdcError(Exception):
    """Bad input or a failed tool run; the message names the file, the element and the problem."""
