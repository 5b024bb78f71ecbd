"""The EDS text: bytes -> characters (:mod:`.source`), tokens (:mod:`.lexicon`, grammar/eds.lark),
the lossless syntax model (:mod:`.reader`, :mod:`.syntax`) and back to text (:mod:`.writer`,
:mod:`.canonical`); a typed Device back to the syntax model (:mod:`.from_model`)."""
