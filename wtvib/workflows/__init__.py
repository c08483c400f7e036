"""The commands as library calls above the audit and its outputs: batches over a catalogue
(:mod:`.batch`), the catalogue that ships with wtvib (:mod:`.catalogue`) and the JSON
contract of the documents (:mod:`.contract`).
"""
