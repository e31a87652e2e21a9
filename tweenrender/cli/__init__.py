"""The ``tweenrender`` command line: :mod:`.main` parses and maps errors to exit codes; one module per
command (named after it), each a ``register(subparsers)`` and a ``run(args) -> int`` that calls the library."""
