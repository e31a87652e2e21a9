"""Rendering on a dask.distributed cluster: a LocalCluster of two single-threaded processes gives the
local render's frames; addresses are checked; the package works without dask."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from tests.helpers import SQUARE, decode, read_png, write_scene

distributed = pytest.importorskip("distributed", reason="dask.distributed is not installed (the cluster extra)")

SMALL = SQUARE.replace("size = [320, 240]", "size = [160, 120]").replace("time = 2\n", "time = 1\n")


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=":0") as cluster, distributed.Client(cluster) as client:
        yield client


def _job(tmp_path: Path):  # type: ignore[no-untyped-def]
    from tweenrender.plan.job import RenderJob
    from tweenrender.scenefile import load_scene

    return RenderJob(load_scene(write_scene(tmp_path, SMALL)))


@pytest.mark.parametrize("fmt", ["png", "gif", "mp4"])
def test_cluster_chunks_give_the_local_renders_frames(tmp_path: Path, client, fmt: str) -> None:  # type: ignore[no-untyped-def]
    from tweenrender.pipeline.chunks import render_chunks
    from tweenrender.pipeline.stream import render

    job = _job(tmp_path)
    name = "frames" if fmt == "png" else f"clip.{fmt}"
    local = render(job, fmt, tmp_path / "local" / name)
    remote = render_chunks(job, fmt, tmp_path / "remote" / name, client.get_executor(), chunks=4)
    if fmt == "png":
        names = sorted(p.name for p in local.glob("*.png"))
        assert len(names) == 25 and names == sorted(p.name for p in remote.glob("*.png"))
        assert all(np.array_equal(read_png(local / n), read_png(remote / n)) for n in names)
    elif fmt == "gif":
        assert local.read_bytes() == remote.read_bytes()
    else:
        (_, here), (_, there) = decode(local), decode(remote)
        assert len(here) == len(there) == 25
        assert all(np.abs(a.astype(int) - b.astype(int)).mean() < 1.5 for a, b in zip(here, there))


def test_the_capacity_is_the_clusters_worker_count(client) -> None:  # type: ignore[no-untyped-def]
    from tweenrender.pipeline.cluster import connect

    with connect(client.scheduler.address) as (executor, capacity):
        assert capacity == 2
        assert executor.submit(sum, [1, 2, 3]).result() == 6


def test_cli_renders_on_a_local_cluster(cli, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    scene = write_scene(tmp_path, SMALL)
    code, out, err = cli("render", scene, "-o", tmp_path / "here", "-q")
    assert code == 0, err
    code, out, err = cli("render", scene, "-o", tmp_path / "there", "-q", "--cluster", "local:2")
    assert code == 0, err
    assert out.strip() == str(tmp_path / "there")
    names = sorted(p.name for p in (tmp_path / "here").glob("*.png"))
    assert len(names) == 25 and names == sorted(p.name for p in (tmp_path / "there").glob("*.png"))
    assert all(np.array_equal(read_png(tmp_path / "here" / n), read_png(tmp_path / "there" / n)) for n in names)


def test_cluster_addresses_and_refusals(cli, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    from tweenrender.errors import OptionError
    from tweenrender.pipeline.cluster import cluster_chunks
    from tweenrender.plan.cluster_address import parse_address

    assert parse_address("local:3") == ("local", 3)
    assert parse_address(" tcp://10.0.0.5:8786 ") == ("tcp://10.0.0.5:8786", None)
    for bad in ("local:x", "local:0", "local:999", ""):
        with pytest.raises(OptionError, match="cluster"):
            parse_address(bad)
    assert cluster_chunks(25, 2) == 2 and cluster_chunks(240, 2) == 8 and cluster_chunks(3, 8) == 3
    scene = write_scene(tmp_path, SMALL)
    code, _, err = cli("render", scene, "-o", tmp_path / "x.mp4", "--cluster", "local:2", "--workers", "2")
    assert code == 2 and "workers and cluster do not go together" in err
    code, _, err = cli("render", scene, "-o", tmp_path / "x.mp4", "--cluster", "local:zero")
    assert code == 2 and err.count("\n") == 1 and "local:N" in err and "Traceback" not in err
    assert not (tmp_path / "x.mp4").exists()


def test_without_dask_a_cluster_is_refused_in_one_line(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    import tweenrender as tr
    from tweenrender.errors import OptionError

    monkeypatch.setitem(sys.modules, "distributed", None)  # import distributed now raises ImportError
    scene = tr.load_scene(write_scene(tmp_path, SMALL))
    with pytest.raises(OptionError, match=r'pip install "tweenrender\[cluster\]"'):
        tr.write(scene, tmp_path / "x.mp4", cluster="local:2")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]
