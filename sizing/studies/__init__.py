"""Studies over many solves or simulations: sizing robust, sizing sweep."""
