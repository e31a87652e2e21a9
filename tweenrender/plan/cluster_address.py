"""Where a cluster render goes: a dask scheduler's ``tcp://`` address or ``local:N``, checked before any work."""

from __future__ import annotations

import ipaddress
import re

from ..errors import OptionError, printable

__all__ = ["parse_address"]

_LOCAL_LIMIT = 256
_EXPECTED = "expected tcp://HOST:PORT (a dask scheduler's address) or local:N"
_DEFAULT_PORT = 8786
_HOST = re.compile(r"[A-Za-z0-9](?:[A-Za-z0-9._-]*[A-Za-z0-9])?")
_OTHER_SCHEMES = {
    "tls": "tls:// needs certificates, which tweenrender does not take: reach the scheduler over tcp:// "
           "in a private network or through an SSH tunnel",
    "inproc": "inproc:// reaches only a scheduler inside this very process",
    "ucx": "ucx:// needs the UCX libraries and their dask extra, which tweenrender does not support",
}


def _refuse(text: str, problem: str) -> OptionError:
    return OptionError(f"{_EXPECTED}, found {printable(repr(text))}: {problem}", "cluster")


def parse_address(address: str) -> tuple[str, int | None]:
    """``("local", N)`` for ``local:N`` (a LocalCluster of N processes), else ``("tcp://HOST:PORT", None)``.

    Only what can work is taken: ``tcp://`` (or no scheme, with a port), a host name or an IP
    address (IPv6 in brackets), a port from 1 to 65535 (8786, dask's, when a ``tcp://`` address
    has none). Anything else is an :class:`OptionError` before any connection is tried.
    """
    text = str(address).strip()
    if not text:
        raise OptionError(f"{_EXPECTED}, found an empty address", "cluster")
    if text.lower().startswith("local:") or text.lower() == "local":
        _, _, count = text.partition(":")
        try:
            processes = int(count)
        except ValueError:
            raise OptionError(f"expected local:N with N a whole number of processes, found {printable(repr(text))}",
                              "cluster") from None
        if not 1 <= processes <= _LOCAL_LIMIT:
            raise OptionError(f"expected local:N with N from 1 to {_LOCAL_LIMIT}, found {printable(repr(text))}",
                              "cluster")
        return "local", processes
    scheme, separator, rest = text.partition("://")
    if not separator:
        scheme, rest = "tcp", text
    scheme = scheme.lower()
    if scheme != "tcp":
        reason = _OTHER_SCHEMES.get(scheme, "a scheme dask's schedulers do not speak")
        raise _refuse(text, f"the {scheme}:// scheme ({reason})")
    if rest.startswith("["):
        close = rest.find("]")
        if close < 0:
            raise _refuse(text, "an IPv6 address without its closing ]")
        host, after = rest[1:close], rest[close + 1:]
        try:
            ipaddress.IPv6Address(host)
        except ValueError:
            raise _refuse(text, f"{printable(repr(host))}, not an IPv6 address") from None
        shown = f"[{host}]"
        if after and not after.startswith(":"):
            raise _refuse(text, f"{printable(repr(after))} after the address")
        port_text = after[1:] if after else None
    else:
        if rest.count(":") > 1:
            raise _refuse(text, "an IPv6 address without brackets (write tcp://[ADDRESS]:PORT)")
        host, colon, port_text_found = rest.partition(":")
        port_text = port_text_found if colon else None
        if not host:
            raise _refuse(text, "no host")
        if not _HOST.fullmatch(host):
            raise _refuse(text, f"the host {printable(repr(host))} (letters, digits, dots and hyphens only)")
        shown = host
    if port_text is None:
        if not separator:
            raise _refuse(text, "no scheme and no port")
        port = _DEFAULT_PORT
    else:
        if not port_text.isascii() or not port_text.isdigit():
            raise _refuse(text, f"the port {printable(repr(port_text))}, not a number")
        port = int(port_text)
        if not 1 <= port <= 65535:
            raise _refuse(text, f"port {port} (ports run from 1 to 65535)")
    return f"tcp://{shown}:{port}", None
