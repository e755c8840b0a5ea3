"""forces"""
