"""The technologies the solve sizes and ranks, one package each."""
