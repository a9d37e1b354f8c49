"""remainder: the modified Hamiltonian of a scheme (placeholder until bound)."""


class Remainder:
    pass


def remainder(*args, **kwargs):
    raise NotImplementedError("rotlie.remainder is not bound yet")
