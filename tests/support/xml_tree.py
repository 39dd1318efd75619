"""Reading the lxml trees the tests check: the attributes a well-formed document must carry."""
from __future__ import annotations

from lxml import etree


def attribute(element: etree._Element, name: str) -> str:
    """``element``'s attribute ``name``, which the document must give it (an AssertionError naming it otherwise)."""
    value = element.get(name)
    assert value is not None, f"<{etree.QName(element).localname}> (line {element.sourceline}) has no {name}="
    return value
