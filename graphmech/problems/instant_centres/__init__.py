"""instant_centres"""
