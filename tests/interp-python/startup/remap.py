"""no functions here"""
