# layout sources (filled in by the layout work)
