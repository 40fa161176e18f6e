"""The expression model: the bilinear style/content model of Chuang & Bregler (2005) §3, which
separates how a face speaks (content) from the emotion it speaks in (style, the paper's word).

One name for one concept: the command (``facesynth expression``), its artifact kind and
settings section (``expression``), this package and its artifact's object
(:class:`facesynth.model.expression.ExpressionModel`) all say *expression*. :mod:`.bilinear`
holds the maths (:class:`~.bilinear.BilinearModel`, the fitted factors themselves),
:mod:`.training` fits it on takes aligned phone by phone, :mod:`.analysis` analyses and restyles
marker motion with it.
"""
