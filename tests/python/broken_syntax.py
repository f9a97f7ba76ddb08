class Broken:
    def control_step(self, node)
        pass
