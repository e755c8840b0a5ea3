"""Constructions: named steps, the step graph, pruning and evaluation."""
from graphmech.construction.graph import BatchSolution, Construction, Plan, Solution, Step

__all__ = ["Construction", "Plan", "Step", "Solution", "BatchSolution"]
