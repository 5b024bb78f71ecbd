"""The ISO 15745-4 XML side: safe parsing (:mod:`.safe`), the restored schemas (:mod:`.schemas`),
validation (:mod:`.validate`), the device and network profiles both ways (:mod:`.device`,
:mod:`.commnet`) and whole conversions (:mod:`.convert`)."""
