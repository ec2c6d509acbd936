"""Who can join a coupled run (docs/coupling.md, "Who can join a run").

On one machine the processes meet at an ipc:// socket in DIR/private, a
folder only the user can enter. Over tcp:// every run gets fresh CURVE keys
(cosph-keys) in that folder: the coupler admits only its solvers' keys, and
the solvers only the coupler's. A wildcard address, listening on every
network interface, needs --bind-any."""

import os
import subprocess

from .errors import UsageError
from .locate import exe_path
from .resume import part_of

PRIVATE = "private"
WILDCARD_HOSTS = ("*", "0.0.0.0", "[::]", "::", "[*]")


def private_dir(out):
    return out / PRIVATE


def default_endpoint(out):
    return f"ipc://{private_dir(out)}/coupler.sock"


def is_tcp(endpoint):
    return endpoint.startswith("tcp://")


def check_bind(endpoint, bind_any):
    """Refuses a wildcard tcp address unless --bind-any says it is meant."""
    host = endpoint[len("tcp://"):].rpartition(":")[0] if is_tcp(endpoint) else ""
    if host in WILDCARD_HOSTS and not bind_any:
        raise UsageError(f"--endpoint {endpoint} listens on every network interface, where any "
                         f"host that reaches the port can try to join the run; give the address "
                         f"of one interface (e.g. tcp://192.168.1.10:5555), or add --bind-any if "
                         f"every interface is meant")


def key_args(names, out, endpoint, bind_any):
    """The arguments each process needs beyond the endpoint: over tcp, its key
    pair and the public keys of its peers (written by make_private_dir), and
    the coupler's --bind-any."""
    extra = {name: [] for name in names}
    keys = private_dir(out)
    if is_tcp(endpoint) and "cosph-coupler" in names:
        extra["cosph-coupler"] = ["--keys", str(keys / "coupler.key")]
        for name in names:
            if name != "cosph-coupler":
                extra["cosph-coupler"] += ["--allow-key", str(keys / f"{part_of(name)}.pub")]
                extra[name] = ["--keys", str(keys / f"{part_of(name)}.key"),
                               "--coupler-key", str(keys / "coupler.pub")]
    if bind_any and "cosph-coupler" in names:
        extra["cosph-coupler"].append("--bind-any")
    return extra


def with_key_args(commands, names, out, endpoint, bind_any):
    extra = key_args(names, out, endpoint, bind_any)
    return [command + extra[name] for command, name in zip(commands, names)]


def make_private_dir(out, folder, endpoint, names):
    """DIR/private, mode 0700, and over tcp a fresh key pair for every process."""
    path = private_dir(out)
    try:
        path.mkdir(mode=0o700, parents=True, exist_ok=True)
        os.chmod(path, 0o700)
    except OSError as err:
        raise UsageError(f"cannot make {path} (mode 0700): {err.strerror}") from err
    if not (is_tcp(endpoint) and "cosph-coupler" in names):
        return
    cmd = [str(exe_path(folder, "cosph-keys")), "--out", str(path)] + [part_of(n) for n in names]
    result = subprocess.run(cmd, stdin=subprocess.DEVNULL, capture_output=True, text=True)
    if result.returncode != 0:
        raise UsageError(f"cannot make the run's keys: {result.stderr.strip() or cmd}")
