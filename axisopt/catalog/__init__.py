"""The part catalogs: what a part of each table is and where its numbers come from.

:mod:`.columns` declares every table's columns once (unit kind, model parameter, positive / optional
/ estimated, choices) and the rules one row keeps; :mod:`.loading` reads and validates
``catalogs/*.csv`` (and a user's catalog directory) into a :class:`~.loading.Catalog`;
:mod:`.parttable` holds a table as numpy columns indexed by part id and :mod:`.partrow` shows one
row in vendor units; :mod:`.grades` the screw precision grades (lead error, variation, price
factor).  Nothing here knows of the model, the search or YAML problem files.
"""
