"""model.conforms: a value read from an edsconv:Value must have the shape its model field declares."""

from __future__ import annotations

from typing import Any, Literal

import pytest

from edsconv.model import Device, Rack, Reference
from edsconv.model.conforms import conforms, declared_type
from edsconv.model.values import Revision


@pytest.mark.parametrize(("value", "hint"), [
    (None, int | None), (3, int), ("Module", int | None), (1, float), ([], list[Rack]), ((1, 2), tuple[int, ...]),
    ((1, "a"), tuple[int, str]), ({"a": 1}, dict[str, int]), ("x", Literal["x", "y"]), (object(), Any),
    (Revision(1, 2), Revision | None),
])
def test_values_of_the_declared_shape_fit(value, hint):
    assert conforms(value, hint)


@pytest.mark.parametrize(("value", "hint"), [
    (True, list[Rack]), (None, int), ([1], dict[str, int]), ({"a": []}, dict[str, int]), ((1, 2, 3), tuple[int, str]),
    ("z", Literal["x", "y"]), ("1.2", Revision), ([True], list[Rack]),
])
def test_values_of_another_shape_do_not(value, hint):
    assert not conforms(value, hint)


def test_a_dataclass_value_is_checked_field_by_field():
    assert conforms(Rack(1, 65535, 101, 2, 1, 1, (1, 2)), Rack)
    assert not conforms(Rack(1, 65535, 101, 2, 1, 1, [1, 2]), Rack)  # type: ignore[arg-type]  # slots: a tuple


def test_the_declared_type_follows_attributes_list_items_and_dict_values():
    device = Device()
    assert declared_type(device, ["modular", "racks"]) == Any  # no Modular yet: nothing to walk into
    device.parameters["Param1"] = None  # type: ignore[assignment]
    assert declared_type(device, ["identity", "vendor_code"]) == int | None
    assert declared_type(device, ["classifications", "0"]).__name__ == "Classification"
    assert declared_type(device, ["parameters", "Param1"]).__name__ == "Parameter"
    assert declared_type(device, ["parameters", "Param1", "default"]) is Any
    assert conforms(Reference("Param1", "Param", 1), declared_type(device, ["identity"])) is False
