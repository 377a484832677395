"""rigid_body_sim: the node's messages and services, and a client for tests (testing)."""
