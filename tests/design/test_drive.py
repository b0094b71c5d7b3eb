"""The drive stage (valvetrain.design.drive): the stage's spring lines."""

from valvetrain.design.drive import SpringLines
from valvetrain.springs import Characteristic


def test_spring_lines_name_the_lines_there_are_in_drawing_order():
    """The spring figure draws the required line first and the chosen one last, over a pair's outer and inner springs
    (the order of Valve-train practical works (n.d.), Fig. 5.1); one spring has no pair lines."""
    required, chosen = Characteristic(200.0, 20e3, 0.01), Characteristic(220.0, 21e3, 0.01)
    outer, inner = Characteristic(150.0, 14e3, 0.01), Characteristic(70.0, 7e3, 0.01)
    assert SpringLines(required, chosen).named() == (("required", required), ("chosen", chosen))
    assert [name for name, _ in SpringLines(required, chosen, outer, inner).named()] == ["required", "outer", "inner",
                                                                                          "chosen"]
