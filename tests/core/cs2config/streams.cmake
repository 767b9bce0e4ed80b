# streams sources (filled in by the streams work)
