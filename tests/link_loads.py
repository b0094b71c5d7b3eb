"""The loads of a link's checks for the tests of tests/links/ (valvetrain.links.Loads), with the notes of the keys
not given collected as the strength stage collects them."""

from valvetrain.links import Loads


def loads(parts=None, guide_offset=None, cam_force=1000.0, valve_force=600.0, modulus=2.1e11, rocker_ratio=1.6):
    """Loads on ``parts`` (keys as attributes, SI), and the notes of the keys not given, collected as the strength
    stage does."""
    notes = []

    def need(keys, name):
        missing = [k for k in keys if getattr(parts, k.rsplit("_", 1)[0]) is None]
        if missing:
            notes.append(f"{name}: not checked")
        return not missing

    return Loads(parts, cam_force, valve_force, modulus, rocker_ratio, (), guide_offset, need), notes
