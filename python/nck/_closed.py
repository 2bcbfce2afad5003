"""What a closed Session or Machine holds in place of its compiled object:
every use raises ArgumentError 940201 (also a ValueError, as Python's own
"I/O operation on closed file"), instead of an AttributeError on None."""
from ._args import BAD_ARGUMENT
from ._errors import ArgumentError


class _Closed:
    def __init__(self, what):
        self._what = what

    def __getattr__(self, name):
        raise ArgumentError(f"the {self._what} is closed (close() or the end of its with block)", BAD_ARGUMENT)

    def __bool__(self):
        return False

    def refuse(self):
        self.__getattr__("refuse")


def closed(what):
    """The stand-in for a closed `what` ("session", "machine")."""
    return _Closed(what)


def alive(core):
    """The compiled object, or ArgumentError when it stands for a closed one
    (where it is handed on, not called)."""
    if isinstance(core, _Closed):
        core.refuse()
    return core
