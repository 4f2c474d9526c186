"""Third generator of the diagnosis benchmark: campaigns from a published
model with its published parameters (cases.py). numpy only: it imports
nothing from sizing, and nothing from the second generator but its writer and case-set reader."""
