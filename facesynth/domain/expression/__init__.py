"""The style model: the bilinear style/content model of Chuang & Bregler (2005) §3, which
separates how a face speaks (content) from the emotion it speaks in (style).

:mod:`.bilinear` holds the math; its artifact (kind ``expression``, written by ``facesynth
expression fit``) is read and written by :class:`facesynth.model.expression.StyleModel`.
"""
