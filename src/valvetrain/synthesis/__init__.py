"""Cam synthesis: design constraints as functions of a computed design (:mod:`.constraints`)."""
