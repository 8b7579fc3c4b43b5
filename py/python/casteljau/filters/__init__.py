"""ufo2ft filters: ``casteljau.filters.removeOverlaps::RemoveOverlapsFilter``."""
