# accessories sources (filled in by the accessories work)
