"""The bilinear style/content expression model (Chuang & Bregler 2005 §3)."""
