"""What an audit's report becomes: the terminal view and the JSON document
(:mod:`.report`), the figures (:mod:`.plots`), the PDF (:mod:`.pdfreport`, with
:mod:`.pdfpng` and :mod:`.png`), files written without losing anything (:mod:`.files`),
the standard streams as the environment gives them (:mod:`.streams`) and the words they
share (:mod:`.words`). Draws and writes results; computes none.
"""
