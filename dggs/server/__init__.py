"""The OGC API - DGGS server and web map of a cell store (`dggs serve`, optional extra ``dggs[serve]``)."""
