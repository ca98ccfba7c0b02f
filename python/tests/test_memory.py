"""No leak: the resident set stays flat over 1,000 calls of each function."""
import os

import apollonius3d
from conftest import REPOSITORY, run_cli


def resident_mib():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2**20


def growth_over_calls(call, calls=1000, warm_up=100):
    for _ in range(warm_up):  # allocator pools, TBB's threads, numpy's caches
        call()
    before = resident_mib()
    for _ in range(calls):
        call()
    return resident_mib() - before


def test_no_leak_over_1000_calls(tmp_path, pept_pdb):
    sites = apollonius3d.read_sites(pept_pdb)
    # diagram() on a small input (0.02 s a call): 1,000 of its results kept alive take 7.5 MiB.
    small = apollonius3d.read_sites(REPOSITORY / "tests" / "data" / "vdrc" / "ANO3_3CONNECT.txt")
    claim = tmp_path / "pept.txt"
    assert run_cli("vertices", pept_pdb, "-o", claim)[0] == 0
    # A leak of what one call computes would show: pept's 550 vertices are about 100 KB as a diagram, so
    # 1,000 lost results would be about 100 MB; the threshold leaves room for the allocator's slack.
    for name, call in [("read_sites", lambda: apollonius3d.read_sites(pept_pdb)),
                       ("vertices", lambda: apollonius3d.vertices(*sites, stats=True)),
                       ("diagram", lambda: apollonius3d.diagram(*small)),
                       ("certify", lambda: apollonius3d.certify(*sites, claim)),
                       ("bad input", lambda: bad_call(sites))]:
        growth = growth_over_calls(call)
        print(f"{name}: resident set grew {growth:.2f} MiB over 1,000 calls")
        assert growth < 4, f"{name}: {growth:.1f} MiB over 1,000 calls"


def bad_call(sites):
    centres = sites.centres.copy()
    centres[50, 1] = float("nan")
    try:
        apollonius3d.vertices(centres, sites.weights)
    except ValueError:
        return
    raise AssertionError("no ValueError")
