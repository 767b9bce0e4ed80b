# locomotives sources (filled in by the locomotives work)
