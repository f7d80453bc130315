"""The reproduction of section 4 of the paper (``results/`` and its README), as sections: :mod:`.section` (what a
section computes, writes and renders) and :mod:`.markdown` (the one table helper every section uses). The package sits
at the ``app`` layer."""
