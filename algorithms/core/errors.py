"""Errors shared by the algorithm modules."""


class InputError(ValueError):
    """Bad input from a person: the message is shown as it is."""
