# The Python module rigid_body_sim.testing, installed by catkin_python_setup().
from setuptools import setup
from catkin_pkg.python_setup import generate_distutils_setup

setup(**generate_distutils_setup(packages=['rigid_body_sim'], package_dir={'': 'src'}))
